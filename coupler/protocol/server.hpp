// The coupler side of the protocol: one ROUTER socket; each participant is a DEALER whose
// identity is its name.
#pragma once

#include <chrono>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <zmq.hpp>

#include "coupler/protocol/curve.hpp"
#include "coupler/protocol/message.hpp"
#include "coupler/protocol/socket_events.hpp"
#include "coupler/protocol/zap_handler.hpp"

namespace cosim::protocol {

// A failure that belongs to one participant: it cannot be reached, or what it sent is not
// a valid message. what() = "participant '<peer>' <problem>".
struct PeerError : ProtocolError {
  PeerError(std::string peer, std::string problem)
      : ProtocolError("participant '" + peer + "' " + problem), peer(std::move(peer)), problem(std::move(problem)) {}
  std::string peer;
  std::string problem;
};

struct ServerOptions {
  // With keys, only clients holding a participant's key get in, each under that
  // participant's name; without, anyone who can reach the endpoint (an ipc socket in a
  // private folder).
  std::optional<curve::ServerKeys> curve;
  // A connection whose peer answers no ZMTP heartbeat for this long is dropped and its
  // participant reported lost; zero: no heartbeats.
  std::chrono::milliseconds heartbeat{0};
};

class Server {
 public:
  // Binds endpoint: "ipc:///path" or "tcp://127.0.0.1:0" (port 0 = pick a free one).
  explicit Server(const std::string& endpoint, ServerOptions options = {});
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;
  // The bound address, with the chosen port for tcp; give this to participants.
  const std::string& endpoint() const { return endpoint_; }

  // Sends m with its participant field set to the addressee, in the protocol version of the
  // addressee's last message (kVersion before it sent one). A name that is not connected, or
  // an array the addressee's version lacks, throws PeerError.
  void send(const std::string& participant, const Message& m);
  // Next message from any participant, or nullopt after timeout (or sooner, when a signal
  // interrupts the wait). The ZeroMQ identity must match the name in the header, else
  // ProtocolError. With CURVE, a message under another name than its key's is dropped and
  // counted among the refusals.
  std::optional<Message> receive(std::chrono::milliseconds timeout);

  // What was refused since the last call, a line each for the log: handshakes that failed,
  // keys that are not the run's, names a key does not carry.
  std::vector<std::string> refusals();
  // Names whose connection ended since the last call (closed, or silent past the
  // heartbeat): a name counts once it has sent a message.
  std::vector<std::string> lost();

 private:
  // Answers ZAP requests and takes monitor events until the ROUTER has a message or the
  // time is up; false on timeout or a signal.
  bool wait(std::chrono::milliseconds timeout);

  zmq::context_t context_;
  ServerOptions options_;
  std::optional<ZapHandler> zap_;  // before the ROUTER binds, so no handshake goes unchecked
  zmq::socket_t socket_;
  SocketEvents events_;  // failed handshakes, ended connections
  std::string endpoint_;
  std::map<int, std::string> names_by_fd_;         // connections that sent messages, by their name
  std::map<std::string, std::uint16_t> versions_;  // each participant's protocol version, answered in
  std::vector<std::string> refusals_;
  std::vector<std::string> lost_;
};

}  // namespace cosim::protocol
