#include "coupler/protocol/socket.hpp"

#include <cerrno>
#include <iterator>

#include <zmq_addon.hpp>

namespace cosim::protocol::socket {

void configure(zmq::socket_t& s, std::chrono::milliseconds linger) {
  s.set(zmq::sockopt::linger, static_cast<int>(linger.count()));
  s.set(zmq::sockopt::sndhwm, 0);
  s.set(zmq::sockopt::rcvhwm, 0);
}

bool readable(zmq::socket_t& s, std::chrono::milliseconds timeout) {
  zmq::pollitem_t item{s.handle(), 0, ZMQ_POLLIN, 0};
  try {
    return zmq::poll(&item, 1, timeout) > 0;
  } catch (const zmq::error_t& e) {
    if (e.num() == EINTR) return false;
    throw;
  }
}

std::vector<zmq::message_t> receive(zmq::socket_t& s) {
  std::vector<zmq::message_t> frames;
  // ZeroMQ delivers the parts of a message together: once readable, this never blocks.
  (void)zmq::recv_multipart(s, std::back_inserter(frames));
  return frames;
}

}  // namespace cosim::protocol::socket
