#include "protocol/server.hpp"

#include <cerrno>

#include <zmq_addon.hpp>

#include "protocol/rules.hpp"
#include "protocol/socket.hpp"

namespace cosim::protocol {
namespace {

// A last Stop or Abort still reaches live participants; a dead one cannot delay exit long.
constexpr std::chrono::milliseconds kLinger(1000);

}  // namespace

Server::Server(const std::string& endpoint) : socket_(context_, zmq::socket_type::router) {
  // Sending to a name nobody connected under fails loudly instead of vanishing.
  socket_.set(zmq::sockopt::router_mandatory, true);
  socket::configure(socket_, kLinger);
  try {
    socket_.bind(endpoint);
  } catch (const zmq::error_t& e) {
    throw ProtocolError("the coupler cannot listen on '" + endpoint + "': " + e.what());
  }
  endpoint_ = socket_.get(zmq::sockopt::last_endpoint);
}

void Server::send(const std::string& participant, const Message& m) {
  Header header = m.header;
  header.participant = participant;
  auto frames = encode(header, m.arrays);
  try {
    socket_.send(zmq::buffer(participant), zmq::send_flags::sndmore);
  } catch (const zmq::error_t& e) {
    if (e.num() != EHOSTUNREACH) throw;
    throw PeerError(participant, "is not connected to the coupler");
  }
  zmq::send_multipart(socket_, frames);
}

std::optional<Message> Server::receive(std::chrono::milliseconds timeout) {
  if (!socket::readable(socket_, timeout)) return std::nullopt;
  auto frames = socket::receive(socket_);
  // ROUTER puts the sender's identity first: the name it connected under.
  const std::string peer = rules::printable(frames.front().to_string_view());
  Message m;
  try {
    m = decode(std::span(frames).subspan(1));
  } catch (const ProtocolError& e) {
    throw PeerError(peer, std::string("sent a message the coupler cannot read: ") + e.what());
  }
  if (m.header.participant != frames.front().to_string_view())
    throw PeerError(peer, "sent a message signed '" + m.header.participant + "'");
  return m;
}

}  // namespace cosim::protocol
