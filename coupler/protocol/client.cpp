#include "coupler/protocol/client.hpp"

#include <algorithm>
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

Client::Client(const std::string& endpoint, const std::string& name, const std::optional<curve::ClientKeys>& keys)
    : socket_(context_, zmq::socket_type::dealer), name_(name) {
  check_participant_name(name);
  socket_.set(zmq::sockopt::routing_id, name);
  socket::configure(socket_, kLinger);
  socket_.set(zmq::sockopt::ipv6, true);  // a coupler bound to an IPv6 address; IPv4 works as before
  if (keys) {
    curve::require();
    curve::use_keys(socket_, *keys);
  }
  try {
    socket_.connect(endpoint);
  } catch (const zmq::error_t& e) {
    throw ProtocolError("participant '" + name + "' cannot connect to '" + endpoint +
                        "': " + e.what());
  }
}

std::optional<Client> Client::from_environment() {
  const char* endpoint = std::getenv(kEndpointEnv);
  const char* name = std::getenv(kParticipantEnv);
  if (!endpoint && !name) return std::nullopt;
  if (!endpoint || !name)
    throw ProtocolError(std::string(endpoint ? kEndpointEnv : kParticipantEnv) +
                        " is set but " + (endpoint ? kParticipantEnv : kEndpointEnv) +
                        " is not");
  return Client(endpoint, name, curve::from_environment());
}

Message Client::hello(std::uint32_t provides, std::uint32_t needs, std::uint32_t ranks) {
  reply(messages::hello(provides, needs, ranks));
  return wait_for({Type::Init});
}

Message Client::wait_for(std::initializer_list<Type> types, std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  auto left = timeout;
  while (!socket::readable(socket_, left)) {  // a signal ends a wait early: wait on
    left = std::chrono::ceil<std::chrono::milliseconds>(deadline -
                                                         std::chrono::steady_clock::now());
    if (left <= left.zero())
      throw ProtocolError("participant '" + name_ + "' waited " +
                          std::to_string(timeout.count()) + " ms for " + one_of(types) +
                          " and the coupler sent nothing");
  }
  Message m = decode(socket::receive(socket_));
  if (std::ranges::find(types, m.header.type) != types.end()) return m;
  if (m.header.type == Type::Abort) {
    const Array* why = m.find(Tag::Text);
    throw Aborted("the coupler aborted the run" + (why ? ": " + why->bytes : std::string()));
  }
  throw ProtocolError("participant '" + name_ + "' expected " + one_of(types) +
                      " from the coupler and received " + to_string(m.header.type));
}

void Client::reply(Message m) {
  m.header.participant = name_;
  zmq::send_multipart(socket_, encode(m));
}

void Client::error(const std::string& text) { reply(messages::error(text)); }

}  // namespace cosim::protocol
