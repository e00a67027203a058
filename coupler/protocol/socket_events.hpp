// What happens to the connections of a socket besides its messages, from libzmq's socket
// monitor: handshakes that failed (a client refused) and connections that ended (closed by
// the peer, or no ZMTP heartbeat answered in time).
#pragma once

#include <optional>
#include <string>
#include <variant>

#include <zmq.hpp>

namespace cosim::protocol {

struct HandshakeFailed {
  std::string why;  // for the log: "it does not use CURVE", ...
};
struct Disconnected {
  int fd;  // the connection's file descriptor, as ZMQ_SRCFD gives it on its messages
};
using SocketEvent = std::variant<HandshakeFailed, Disconnected>;

class SocketEvents {
 public:
  SocketEvents(zmq::context_t& context, zmq::socket_t& watched);

  zmq::socket_t& socket() { return socket_; }
  // The waiting event; nullopt for one of no interest (a handshake refused by the ZAP
  // handler, which says why itself).
  std::optional<SocketEvent> next();

 private:
  zmq::socket_t socket_;
};

}  // namespace cosim::protocol
