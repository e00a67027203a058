#include "coupler/protocol/client.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <zmq_addon.hpp>

#include "coupler/protocol/messages.hpp"
#include "coupler/protocol/socket.hpp"

namespace cosim::protocol {
namespace {

// Long enough for a last Bye or Error to leave, short enough that exit never hangs.
constexpr std::chrono::milliseconds kLinger(1000);

std::string one_of(std::initializer_list<Type> types) {
  std::string out;
  for (Type t : types) out += (out.empty() ? "" : " or ") + std::string(to_string(t));
  return out;
}

}  // namespace

Client::Client(const std::string& endpoint, const std::string& name, const std::optional<curve::ClientKeys>& keys,
               std::chrono::milliseconds heartbeat)
    : socket_(context_, zmq::socket_type::dealer), name_(name), endpoint_(endpoint), heartbeat_(heartbeat) {
  check_participant_name(name);
  socket_.set(zmq::sockopt::routing_id, name);
  socket::configure(socket_, kLinger);
  if (heartbeat.count() > 0) {
    const int half = static_cast<int>(std::max<long>(1, heartbeat.count() / 2));
    socket_.set(zmq::sockopt::heartbeat_ivl, half);
    socket_.set(zmq::sockopt::heartbeat_timeout, half);
  }
  // Watched from before the first connection, so that no end of it goes unseen.
  events_ = std::make_unique<SocketEvents>(context_, socket_);
  socket_.set(zmq::sockopt::ipv6, true);  // a coupler bound to an IPv6 address; IPv4 works as before
  if (keys) {
    curve::require();
    curve::use_keys(socket_, *keys);
  }
  try {
    socket_.connect(endpoint);
  } catch (const zmq::error_t& e) {
    throw ProtocolError("participant '" + name + "' cannot connect to '" + endpoint + "': " + e.what());
  }
}

std::optional<Client> Client::from_environment() {
  const char* endpoint = std::getenv(kEndpointEnv);
  const char* name = std::getenv(kParticipantEnv);
  if (!endpoint && !name) return std::nullopt;
  if (!endpoint || !name)
    throw ProtocolError(std::string(endpoint ? kEndpointEnv : kParticipantEnv) + " is set but " +
                        (endpoint ? kParticipantEnv : kEndpointEnv) + " is not");
  std::chrono::milliseconds heartbeat(0);
  if (const char* seconds = std::getenv(kHeartbeatEnv)) {
    char* end = nullptr;
    const double s = std::strtod(seconds, &end);
    if (end == seconds || *end != '\0' || !(s > 0) || s > 1e6)
      throw ProtocolError(std::string(kHeartbeatEnv) + " = '" + seconds + "': expected seconds > 0");
    heartbeat = std::chrono::milliseconds(std::lround(s * 1000));
  }
  return Client(endpoint, name, curve::from_environment(), heartbeat);
}

Message Client::hello(std::uint32_t provides, std::uint32_t needs, std::uint32_t ranks) {
  reply(messages::hello(provides, needs, ranks));
  return wait_for({Type::Init});
}

Message Client::wait_for(std::initializer_list<Type> types, std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    const auto left = std::chrono::ceil<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left <= left.zero())
      throw ProtocolError("participant '" + name_ + "' waited " + std::to_string(timeout.count()) + " ms for " +
                          one_of(types) + " and the coupler sent nothing");
    std::vector<zmq::pollitem_t> items{{socket_.handle(), 0, ZMQ_POLLIN, 0},
                                       {events_->socket().handle(), 0, ZMQ_POLLIN, 0}};
    try {
      zmq::poll(items, left);
    } catch (const zmq::error_t& e) {
      if (e.num() != EINTR) throw;
      continue;  // a signal ends a wait early: wait on
    }
    if (items[0].revents & ZMQ_POLLIN) break;
    if (items[1].revents & ZMQ_POLLIN) check_connection();
  }
  Message m = decode(socket::receive(socket_));
  if (std::ranges::find(types, m.header.type) != types.end()) return m;
  if (m.header.type == Type::Abort) {
    const Array* why = m.find(Tag::Text);
    throw Aborted("the coupler aborted the run" + (why ? ": " + why->bytes : std::string()));
  }
  throw ProtocolError("participant '" + name_ + "' expected " + one_of(types) + " from the coupler and received " +
                      to_string(m.header.type));
}

void Client::check_connection() {
  const auto event = events_->next();
  if (!event) return;
  if (const auto* refused = std::get_if<HandshakeFailed>(&*event))
    throw ProtocolError("participant '" + name_ + "': the coupler at " + endpoint_ + " refused its handshake (" +
                        refused->why + ")");
  std::string heartbeat;
  if (heartbeat_.count() > 0) {
    char text[96];
    std::snprintf(text, sizeof text, ", or it answered no heartbeat for %ld ms (coupling.heartbeat %g s)",
                  static_cast<long>(heartbeat_.count() / 2), heartbeat_.count() / 1000.0);
    heartbeat = text;
  }
  throw ProtocolError("participant '" + name_ + "' lost the coupler at " + endpoint_ + ": the connection closed" +
                      heartbeat);
}

void Client::reply(Message m) {
  m.header.participant = name_;
  zmq::send_multipart(socket_, encode(m));
}

void Client::error(const std::string& text) { reply(messages::error(text)); }

}  // namespace cosim::protocol
