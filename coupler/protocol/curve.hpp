// ZeroMQ CURVE keys: every tcp run encrypts and authenticates its connections with keys made
// for that run alone (docs/security.md says what this protects against).
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include <zmq.hpp>

namespace cosim::protocol::curve {

// The launch environment carries a participant's keys (the environment of a process is
// readable only by its user); the coupler's secret key never leaves its host.
inline constexpr const char* kServerKeyEnv = "COSIM_CURVE_SERVER_KEY";  // the coupler's public key
inline constexpr const char* kPublicKeyEnv = "COSIM_CURVE_PUBLIC_KEY";  // the participant's own pair
inline constexpr const char* kSecretKeyEnv = "COSIM_CURVE_SECRET_KEY";

struct KeyPair {
  std::string public_key;  // Z85 text, 40 characters
  std::string secret_key;
};

// What a participant needs to connect: the coupler's public key and its own pair.
struct ClientKeys {
  std::string server_key;
  KeyPair own;
};

// What the coupler needs: its pair, and the public key of each participant by name.
struct ServerKeys {
  KeyPair own;
  std::map<std::string, std::string> participants;  // public key -> participant name
};

// Sets a CURVE key option (ZMQ_CURVE_SERVERKEY, _PUBLICKEY, _SECRETKEY) from Z85 text,
// which libzmq takes only with its terminating NUL.
void set_key(zmq::socket_t& socket, int option, const std::string& z85);

// Makes `socket` a CURVE client with these keys (before it connects).
void use_keys(zmq::socket_t& socket, const ClientKeys& keys);

// Throws ProtocolError when the libzmq in use was built without CURVE (libsodium).
void require();
KeyPair make_keypair();

// Writes a pair to `file` (public key, then secret key, one a line), created readable by
// this user alone (0600) from the start, so the secret is never readable by others even for
// a moment. An existing file is an error: keys are never reused across runs.
void write_keypair(const std::filesystem::path& file, const KeyPair& pair);

// The three variables above, or nullopt when none is set; some but not all throws.
std::optional<ClientKeys> from_environment();
std::map<std::string, std::string> environment(const ClientKeys& keys);

}  // namespace cosim::protocol::curve
