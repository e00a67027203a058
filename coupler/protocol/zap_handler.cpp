#include "coupler/protocol/zap_handler.hpp"

#include <array>
#include <vector>

#include <zmq_addon.hpp>

#include "coupler/protocol/rules.hpp"

namespace cosim::protocol {
namespace {

constexpr std::size_t kKeyBytes = 32;

// The request frames (RFC 27): version, request id, domain, address, identity, mechanism,
// then the mechanism's credentials (CURVE: the client's 32-byte public key).
enum Frame : std::size_t { kZapVersion, kRequestId, kDomain, kAddress, kIdentity, kMechanism, kKey };

std::string z85(const zmq::message_t& key) {
  std::array<char, 41> text{};
  zmq_z85_encode(text.data(), key.data<std::uint8_t>(), kKeyBytes);
  return text.data();
}

}  // namespace

ZapHandler::ZapHandler(zmq::context_t& context, const curve::ServerKeys& keys)
    : socket_(context, zmq::socket_type::rep), keys_(keys) {
  socket_.set(zmq::sockopt::linger, 0);
  socket_.bind("inproc://zeromq.zap.01");
}

std::optional<std::string> ZapHandler::answer() {
  std::vector<zmq::message_t> request;
  (void)zmq::recv_multipart(socket_, std::back_inserter(request));
  const auto frame = [&](std::size_t i) { return i < request.size() ? request[i].to_string() : std::string(); };
  std::optional<std::string> refusal;
  std::string name;
  if (request.size() <= kKey || frame(kZapVersion) != "1.0" || frame(kMechanism) != "CURVE" ||
      request[kKey].size() != kKeyBytes) {
    refusal = "refused a connection from " + rules::printable(frame(kAddress)) + ": not a CURVE handshake";
  } else if (auto it = keys_.participants.find(z85(request[kKey])); it != keys_.participants.end()) {
    name = it->second;
  } else {
    refusal = "refused a connection from " + rules::printable(frame(kAddress)) + ": its key is not one of this run's";
  }
  // The reply: version, request id, status code and text, user id, metadata.
  const std::string request_id = request.size() > kRequestId ? request[kRequestId].to_string() : std::string();
  const std::array<zmq::const_buffer, 6> reply{zmq::str_buffer("1.0"),
                                               zmq::buffer(request_id),
                                               refusal ? zmq::str_buffer("400") : zmq::str_buffer("200"),
                                               refusal ? zmq::str_buffer("unknown key") : zmq::str_buffer("OK"),
                                               zmq::buffer(name),
                                               zmq::const_buffer()};
  zmq::send_multipart(socket_, reply);
  return refusal;
}

}  // namespace cosim::protocol
