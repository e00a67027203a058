// The coupler side of the protocol: one ROUTER socket; each participant is a DEALER whose
// identity is its name.
#pragma once

#include <chrono>
#include <optional>
#include <string>

#include <zmq.hpp>

#include "protocol/message.hpp"

namespace cosim::protocol {

// A failure that belongs to one participant: it cannot be reached, or what it sent is not
// a valid message. what() = "participant '<peer>' <problem>".
struct PeerError : ProtocolError {
  PeerError(std::string peer, std::string problem)
      : ProtocolError("participant '" + peer + "' " + problem),
        peer(std::move(peer)),
        problem(std::move(problem)) {}
  std::string peer;
  std::string problem;
};

class Server {
 public:
  // Binds endpoint: "ipc:///path" or "tcp://127.0.0.1:0" (port 0 = pick a free one).
  explicit Server(const std::string& endpoint);
  // The bound address, with the chosen port for tcp; give this to participants.
  const std::string& endpoint() const { return endpoint_; }

  // Sends m with its participant field set to the addressee. A name that is not connected
  // throws ProtocolError.
  void send(const std::string& participant, const Message& m);
  // Next message from any participant, or nullopt after timeout (or sooner, when a signal
  // interrupts the wait). The ZeroMQ identity must match the name in the header, else
  // ProtocolError.
  std::optional<Message> receive(std::chrono::milliseconds timeout);

 private:
  zmq::context_t context_;
  zmq::socket_t socket_;
  std::string endpoint_;
};

}  // namespace cosim::protocol
