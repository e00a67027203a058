// The participant side of the protocol: every adapter (and every test double) talks to
// the coupler through this, never through raw sockets.
#pragma once

#include <chrono>
#include <initializer_list>
#include <memory>
#include <optional>
#include <string>

#include <zmq.hpp>

#include "coupler/protocol/curve.hpp"
#include "coupler/protocol/message.hpp"
#include "coupler/protocol/socket_events.hpp"

namespace cosim::protocol {

// Environment the launcher sets for each child it starts.
inline constexpr const char* kEndpointEnv = "COSIM_ENDPOINT";
inline constexpr const char* kParticipantEnv = "COSIM_PARTICIPANT";
// Seconds of the scene's coupling.heartbeat: how long a participant waits for an answer to
// its ZMTP heartbeats before it takes the coupler for gone.
inline constexpr const char* kHeartbeatEnv = "COSIM_HEARTBEAT";

// Thrown by wait_for() when the coupler sends Abort: the participant should exit now.
struct Aborted : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class Client {
 public:
  // A DEALER socket whose identity is the participant name, connected to endpoint; with
  // keys, over CURVE. With a heartbeat it pings the coupler every half heartbeat and drops
  // the connection when half a heartbeat passes without an answer, as the coupler does on
  // its side (server.hpp).
  Client(const std::string& endpoint, const std::string& name,
         const std::optional<curve::ClientKeys>& keys = std::nullopt,
         std::chrono::milliseconds heartbeat = std::chrono::milliseconds(0));
  // Reads COSIM_ENDPOINT / COSIM_PARTICIPANT, COSIM_HEARTBEAT and the CURVE keys if the
  // coupler gave any; nullopt when not started by the coupler.
  static std::optional<Client> from_environment();

  const std::string& name() const { return name_; }

  // Sends Hello (protocol version, provides, needs, ranks) and returns the Init answer.
  Message hello(std::uint32_t provides, std::uint32_t needs, std::uint32_t ranks = 1);
  // Next message from the coupler, which must be one of `types`. Abort throws Aborted; an
  // unexpected type, a silent coupler (timeout), a connection to the coupler that ended
  // (closed, or its heartbeat unanswered: the coupler or its host is gone) and a handshake
  // the coupler refused throw ProtocolError naming the coupler's endpoint.
  Message wait_for(std::initializer_list<Type> types, std::chrono::milliseconds timeout = std::chrono::hours(24));
  // Sends m with the participant name filled in.
  void reply(Message m);
  // Reports a failure the coupler will show the user, naming this participant.
  void error(const std::string& text);

 private:
  // Throws when the watched connection ended or was refused.
  void check_connection();

  zmq::context_t context_;
  zmq::socket_t socket_;
  std::string name_;
  std::string endpoint_;
  std::chrono::milliseconds heartbeat_;
  std::unique_ptr<SocketEvents> events_;  // the connection's end, seen while waiting
};

}  // namespace cosim::protocol
