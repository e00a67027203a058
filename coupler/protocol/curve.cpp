#include "coupler/protocol/curve.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdlib>
#include <cstring>

#include <zmq.h>

#include "coupler/protocol/message.hpp"

namespace cosim::protocol::curve {

void require() {
  if (zmq_has("curve") == 0)
    throw ProtocolError(
        "this libzmq was built without CURVE (libsodium), which tcp transport needs to "
        "encrypt and authenticate connections; install a libzmq built with libsodium");
}

void set_key(zmq::socket_t& socket, int option, const std::string& z85) {
  if (z85.size() != 40) throw ProtocolError("a CURVE key is 40 characters of Z85, not " + std::to_string(z85.size()));
  if (zmq_setsockopt(socket.handle(), option, z85.c_str(), z85.size() + 1) != 0)
    throw ProtocolError(std::string("cannot set a CURVE key: ") + zmq_strerror(zmq_errno()));
}

void use_keys(zmq::socket_t& socket, const ClientKeys& keys) {
  set_key(socket, ZMQ_CURVE_SERVERKEY, keys.server_key);
  set_key(socket, ZMQ_CURVE_PUBLICKEY, keys.own.public_key);
  set_key(socket, ZMQ_CURVE_SECRETKEY, keys.own.secret_key);
}

KeyPair make_keypair() {
  require();
  std::array<char, 41> pub{}, sec{};
  if (zmq_curve_keypair(pub.data(), sec.data()) != 0)
    throw ProtocolError(std::string("cannot make a CURVE key pair: ") + zmq_strerror(zmq_errno()));
  return {pub.data(), sec.data()};
}

void write_keypair(const std::filesystem::path& file, const KeyPair& pair) {
  const int fd = open(file.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0) throw ProtocolError("cannot create " + file.string() + ": " + std::strerror(errno));
  const std::string text = pair.public_key + "\n" + pair.secret_key + "\n";
  const bool written = write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size());
  close(fd);
  if (!written) throw ProtocolError("cannot write " + file.string());
}

std::optional<ClientKeys> from_environment() {
  const std::array names{kServerKeyEnv, kPublicKeyEnv, kSecretKeyEnv};
  std::array<const char*, 3> values{};
  int set = 0;
  for (std::size_t i = 0; i < names.size(); ++i) set += (values[i] = std::getenv(names[i])) != nullptr;
  if (set == 0) return std::nullopt;
  for (std::size_t i = 0; i < names.size(); ++i)
    if (values[i] == nullptr) throw ProtocolError(std::string(names[i]) + " is not set, but other CURVE keys are");
  return ClientKeys{values[0], {values[1], values[2]}};
}

std::map<std::string, std::string> environment(const ClientKeys& keys) {
  return {{kServerKeyEnv, keys.server_key}, {kPublicKeyEnv, keys.own.public_key}, {kSecretKeyEnv, keys.own.secret_key}};
}

}  // namespace cosim::protocol::curve
