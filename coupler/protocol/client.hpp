// The participant side of the protocol: every adapter (and every test double) talks to
// the coupler through this, never through raw sockets.
#pragma once

#include <chrono>
#include <initializer_list>
#include <optional>
#include <string>

#include <zmq.hpp>

#include "coupler/protocol/curve.hpp"
#include "coupler/protocol/message.hpp"

namespace cosim::protocol {

// Environment the launcher sets for each child it starts.
inline constexpr const char* kEndpointEnv = "COSIM_ENDPOINT";
inline constexpr const char* kParticipantEnv = "COSIM_PARTICIPANT";

// Thrown by wait_for() when the coupler sends Abort: the participant should exit now.
struct Aborted : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class Client {
 public:
  // A DEALER socket whose identity is the participant name, connected to endpoint; with
  // keys, over CURVE.
  Client(const std::string& endpoint, const std::string& name,
         const std::optional<curve::ClientKeys>& keys = std::nullopt);
  // Reads COSIM_ENDPOINT / COSIM_PARTICIPANT and the CURVE keys if the coupler gave any;
  // nullopt when not started by the coupler.
  static std::optional<Client> from_environment();

  const std::string& name() const { return name_; }

  // Sends Hello (protocol version, provides, needs, ranks) and returns the Init answer.
  Message hello(std::uint32_t provides, std::uint32_t needs, std::uint32_t ranks = 1);
  // Next message from the coupler, which must be one of `types`. Abort throws Aborted; an
  // unexpected type or a silent coupler (timeout) throws ProtocolError.
  Message wait_for(std::initializer_list<Type> types,
                   std::chrono::milliseconds timeout = std::chrono::hours(24));
  // Sends m with the participant name filled in.
  void reply(Message m);
  // Reports a failure the coupler will show the user, naming this participant.
  void error(const std::string& text);

 private:
  zmq::context_t context_;
  zmq::socket_t socket_;
  std::string name_;
};

}  // namespace cosim::protocol
