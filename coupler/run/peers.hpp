// The participants as the coupler sees them: a process it started and a name on the
// ROUTER socket. Every wait watches for the three ways a participant fails (its process
// ends, it stays silent past the timeout, it reports an error) and for Ctrl-C.
#pragma once

#include <chrono>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "launcher/process.hpp"
#include "protocol/message.hpp"
#include "protocol/server.hpp"

namespace cosim::run {

class Peers {
 public:
  Peers(protocol::Server& server, std::chrono::milliseconds timeout);
  ~Peers();  // stops every process still running

  void start(const std::string& name, const std::vector<std::string>& command,
             const std::map<std::string, std::string>& env);
  std::vector<std::string> names() const;

  void send(const std::string& name, protocol::Message m);
  // One message of `type` from each of `names`; `window` only labels failures.
  std::map<std::string, protocol::Message> gather(const std::vector<std::string>& names,
                                                  protocol::Type type, std::uint64_t window);
  // Send one message to each, then gather the replies of `reply` type.
  std::map<std::string, protocol::Message> exchange(
      std::map<std::string, protocol::Message> requests, protocol::Type reply,
      std::uint64_t window);

  // Stop (answered by Bye) to all, then wait for the processes; anything left is killed.
  void stop_all(std::uint64_t window);
  // Abort with a reason to all that still run, then end the processes.
  void abort_all(const std::string& reason);

 private:
  protocol::Server& server_;
  std::chrono::milliseconds timeout_;
  std::map<std::string, launcher::Process> processes_;
  std::set<std::string> said_bye_;  // may exit without that being a failure
};

}  // namespace cosim::run
