// The coupler's answer to "may this key connect?" (ZeroMQ's ZAP, RFC 27): libzmq asks over
// an inproc REP socket during every CURVE handshake. Only the keys made for this run's
// participants get in, each under its participant's name as User-Id, which the server then
// holds the ZeroMQ identity to.
#pragma once

#include <optional>
#include <string>

#include <zmq.hpp>

#include "coupler/protocol/curve.hpp"

namespace cosim::protocol {

class ZapHandler {
 public:
  // Binds the handler in `context`; must exist before the socket it guards binds.
  ZapHandler(zmq::context_t& context, const curve::ServerKeys& keys);

  zmq::socket_t& socket() { return socket_; }
  // Answers the waiting request; returns what to log when it refused the key.
  std::optional<std::string> answer();

 private:
  zmq::socket_t socket_;
  const curve::ServerKeys& keys_;
};

}  // namespace cosim::protocol
