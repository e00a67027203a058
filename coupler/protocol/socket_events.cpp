#include "coupler/protocol/socket_events.hpp"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <vector>

#include <zmq_addon.hpp>

namespace cosim::protocol {
namespace {

std::string protocol_error(std::uint32_t code) {
  switch (code) {
    case ZMQ_PROTOCOL_ERROR_ZMTP_MECHANISM_MISMATCH:
      return "it does not use CURVE (no key)";
    case ZMQ_PROTOCOL_ERROR_ZMTP_CRYPTOGRAPHIC:
      return "it does not hold the coupler's public key of this run";
    default: {
      char text[80];
      std::snprintf(text, sizeof text, "it broke the ZMTP handshake (libzmq protocol error %#x)", code);
      return text;
    }
  }
}

}  // namespace

SocketEvents::SocketEvents(zmq::context_t& context, zmq::socket_t& watched) : socket_(context, zmq::socket_type::pair) {
  // Unique per watched socket: a process may hold several servers (tests, benchmarks).
  char address[64];
  std::snprintf(address, sizeof address, "inproc://cosim.events.%p", watched.handle());
  const int events =
      ZMQ_EVENT_DISCONNECTED | ZMQ_EVENT_HANDSHAKE_FAILED_NO_DETAIL | ZMQ_EVENT_HANDSHAKE_FAILED_PROTOCOL;
  if (zmq_socket_monitor(watched.handle(), address, events) != 0) throw zmq::error_t();
  socket_.set(zmq::sockopt::linger, 0);
  socket_.connect(address);
}

std::optional<SocketEvent> SocketEvents::next() {
  std::vector<zmq::message_t> frames;  // event id (u16) and value (u32), then the endpoint
  (void)zmq::recv_multipart(socket_, std::back_inserter(frames));
  if (frames.empty() || frames[0].size() < 6) return std::nullopt;
  std::uint16_t event = 0;
  std::uint32_t value = 0;
  std::memcpy(&event, frames[0].data(), sizeof event);
  std::memcpy(&value, frames[0].data<char>() + sizeof event, sizeof value);
  switch (event) {
    case ZMQ_EVENT_DISCONNECTED:
      return Disconnected{static_cast<int>(value)};
    case ZMQ_EVENT_HANDSHAKE_FAILED_PROTOCOL:
      return HandshakeFailed{protocol_error(value)};
    case ZMQ_EVENT_HANDSHAKE_FAILED_NO_DETAIL:
      return HandshakeFailed{std::string("its handshake failed: ") + zmq_strerror(static_cast<int>(value))};
    default:
      return std::nullopt;
  }
}

}  // namespace cosim::protocol
