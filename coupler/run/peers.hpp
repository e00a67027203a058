// The participants as the coupler sees them: a process it started and a name on the
// ROUTER socket. Every wait watches for the ways a participant fails (its process ends, its
// connection is lost, it stays silent past the timeout, it reports an error or sends
// garbage) and for Ctrl-C. What comes from anyone else is logged and ignored: the run goes on.
// `when` in every call labels failures for the user ("in window 12 (t = ...)").
#pragma once

#include <chrono>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "coupler/launcher/process.hpp"
#include "coupler/protocol/message.hpp"
#include "coupler/protocol/server.hpp"
#include "coupler/run/warning_rate.hpp"

namespace cosim::run {

class Peers {
 public:
  // `heartbeat` is the server's, for the message naming a participant it lost.
  Peers(protocol::Server& server, std::chrono::milliseconds timeout, std::chrono::milliseconds heartbeat);
  ~Peers();  // ends every process still running, and any process they left behind

  void start(const std::string& name, const std::vector<std::string>& command,
             const std::map<std::string, std::string>& env);
  std::vector<std::string> names() const;

  void send(const std::string& name, protocol::Message m, const std::string& when);
  // One message of `type` from each of `names`.
  std::map<std::string, protocol::Message> gather(const std::vector<std::string>& names, protocol::Type type,
                                                  const std::string& when);
  // Send one message to each, then gather the replies of `reply` type.
  std::map<std::string, protocol::Message> exchange(std::map<std::string, protocol::Message> requests,
                                                    protocol::Type reply, const std::string& when);

  // Stop (answered by Bye) to all, then wait for the processes; anything left is killed.
  void stop_all();
  // The peak resident set of each participant's largest process, once stop_all() has ended them.
  std::map<std::string, double> peak_bytes() const;
  // Abort with a reason to all that still run, then end the processes.
  void abort_all(const std::string& reason);

 private:
  [[noreturn]] void fail(const std::string& name, const std::string& problem, const std::string& when);
  // Logs what the server refused (at most once a second: warning_rate.hpp), notes whom it
  // lost.
  void watch_connections();
  std::string lost_connection() const;  // the problem, for fail()
  // Fails the first participant whose connection was lost, unless it had said Bye.
  void check_connections(const std::string& when);

  protocol::Server& server_;
  std::chrono::milliseconds timeout_;
  std::chrono::milliseconds heartbeat_;
  std::map<std::string, launcher::Process> processes_;
  std::set<std::string> said_bye_;  // may exit without that being a failure
  std::set<std::string> lost_;      // connections ended; failed once their last messages are read
  WarningRate refusals_;
};

}  // namespace cosim::run
