#include "coupler/protocol/server.hpp"

#include <algorithm>
#include <cerrno>
#include <utility>

#include <zmq_addon.hpp>

#include "coupler/protocol/rules.hpp"
#include "coupler/protocol/socket.hpp"

namespace cosim::protocol {
namespace {

using clock = std::chrono::steady_clock;

// A last Stop or Abort still reaches live participants; a dead one cannot delay exit long.
constexpr std::chrono::milliseconds kLinger(1000);

}  // namespace

Server::Server(const std::string& endpoint, ServerOptions options)
    : options_(std::move(options)), socket_(context_, zmq::socket_type::router), events_(context_, socket_) {
  // Sending to a name nobody connected under fails loudly instead of vanishing.
  socket_.set(zmq::sockopt::router_mandatory, true);
  socket::configure(socket_, kLinger);
  if (options_.curve) {
    curve::require();
    zap_.emplace(context_, *options_.curve);
    socket_.set(zmq::sockopt::curve_server, true);
    curve::set_key(socket_, ZMQ_CURVE_SECRETKEY, options_.curve->own.secret_key);
  }
  if (options_.heartbeat.count() > 0) {
    // A ping every half heartbeat, and half a heartbeat for its answer: a silent peer is
    // dropped at most one heartbeat after it fell silent.
    const int half = static_cast<int>(options_.heartbeat.count() / 2);
    socket_.set(zmq::sockopt::heartbeat_ivl, half);
    socket_.set(zmq::sockopt::heartbeat_timeout, half);
  }
  if (endpoint.starts_with("tcp://") && endpoint.find('[') != std::string::npos) socket_.set(zmq::sockopt::ipv6, true);
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
  const auto known = versions_.find(participant);
  header.version = known != versions_.end() ? known->second : kVersion;
  std::vector<zmq::message_t> frames;
  try {
    frames = encode(header, m.arrays);
  } catch (const ProtocolError& e) {
    if (header.version == kVersion) throw;
    throw PeerError(participant, "speaks protocol version " + std::to_string(header.version) + ", in which the " +
                                     to_string(header.type) + " message the coupler sends cannot be written (" +
                                     e.what() +
                                     "): build it against this coupler's participant library (C++) or "
                                     "run it with this coupler's cosim_participant (Python)");
  }
  try {
    socket_.send(zmq::buffer(participant), zmq::send_flags::sndmore);
  } catch (const zmq::error_t& e) {
    if (e.num() != EHOSTUNREACH) throw;
    throw PeerError(participant, "is not connected to the coupler");
  }
  zmq::send_multipart(socket_, frames);
}

bool Server::wait(std::chrono::milliseconds timeout) {
  const auto deadline = clock::now() + timeout;
  for (;;) {
    std::vector<zmq::pollitem_t> items{{socket_.handle(), 0, ZMQ_POLLIN, 0},
                                       {events_.socket().handle(), 0, ZMQ_POLLIN, 0}};
    if (zap_) items.push_back({zap_->socket().handle(), 0, ZMQ_POLLIN, 0});
    const auto left =
        std::max(std::chrono::milliseconds(0), std::chrono::ceil<std::chrono::milliseconds>(deadline - clock::now()));
    try {
      zmq::poll(items, left);
    } catch (const zmq::error_t& e) {
      if (e.num() == EINTR) return false;
      throw;
    }
    if (items[1].revents & ZMQ_POLLIN) {
      const auto event = events_.next();
      if (const auto* failed = event ? std::get_if<HandshakeFailed>(&*event) : nullptr)
        refusals_.push_back("refused a connection: " + failed->why);
      if (const auto* ended = event ? std::get_if<Disconnected>(&*event) : nullptr)
        if (const auto it = names_by_fd_.find(ended->fd); it != names_by_fd_.end()) {
          lost_.push_back(it->second);
          names_by_fd_.erase(it);
        }
    }
    if (zap_ && (items[2].revents & ZMQ_POLLIN))
      if (auto refusal = zap_->answer()) refusals_.push_back(std::move(*refusal));
    if (items[0].revents & ZMQ_POLLIN) return true;
    if (clock::now() >= deadline) return false;
  }
}

std::optional<Message> Server::receive(std::chrono::milliseconds timeout) {
  const auto deadline = clock::now() + timeout;
  for (;;) {
    const auto left =
        std::max(std::chrono::milliseconds(0), std::chrono::ceil<std::chrono::milliseconds>(deadline - clock::now()));
    if (!wait(left)) return std::nullopt;
    auto frames = socket::receive(socket_);
    // ROUTER puts the sender's identity first: the name it connected under.
    const std::string_view identity = frames.front().to_string_view();
    const std::string peer = rules::printable(identity);
    if (options_.curve) {
      // The ZAP handler named the key's participant; the identity is the client's own claim.
      // ROUTER makes the identity frame itself: the metadata (and ZMQ_SRCFD below) are on
      // the frames received.
      const std::string_view holder = frames.back().gets("User-Id");
      if (holder != identity) {
        refusals_.push_back("ignored a message from a client holding the key of '" + rules::printable(holder) +
                            "' under the name '" + peer + "'");
        continue;
      }
    }
    names_by_fd_[frames.back().get(ZMQ_SRCFD)] = std::string(identity);
    Message m;
    try {
      m = decode(std::span(frames).subspan(1));
    } catch (const ProtocolError& e) {
      throw PeerError(peer, std::string("sent a message the coupler cannot read: ") + e.what());
    }
    if (m.header.participant != identity) throw PeerError(peer, "sent a message signed '" + m.header.participant + "'");
    versions_[m.header.participant] = m.header.version;
    return m;
  }
}

std::vector<std::string> Server::refusals() { return std::exchange(refusals_, {}); }

std::vector<std::string> Server::lost() { return std::exchange(lost_, {}); }

}  // namespace cosim::protocol
