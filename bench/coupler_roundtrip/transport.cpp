#include "bench/coupler_roundtrip/transport.hpp"

#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <stdexcept>

namespace cosim::bench {
namespace {

// One folder per process, removed at exit; each bind gets its own socket file in it, so a
// run never meets a stale socket left by the previous one.
class SocketFolder {
 public:
  SocketFolder() {
    std::string dir = (std::filesystem::temp_directory_path() / "cosim-bench-XXXXXX").string();
    if (!mkdtemp(dir.data())) throw std::runtime_error("cannot create " + dir);
    path_ = dir;
  }
  ~SocketFolder() { std::filesystem::remove_all(path_); }
  std::string next() { return (path_ / std::to_string(count_++)).string(); }

 private:
  std::filesystem::path path_;
  std::atomic<int> count_{0};
};

}  // namespace

const char* to_string(Transport t) {
  switch (t) {
    case Transport::Ipc:
      return "ipc";
    case Transport::Tcp:
      return "tcp";
    case Transport::Curve:
      return "curve";
  }
  return "?";
}

std::string bind_address(Transport t) {
  static SocketFolder folder;
  switch (t) {
    case Transport::Ipc:
      return "ipc://" + folder.next();
    case Transport::Tcp:
      return "tcp://127.0.0.1:0";
    case Transport::Curve:
      return "tcp://127.0.0.2:0";
  }
  return {};
}

Keys make_keys(const std::vector<std::string>& names) {
  Keys keys{{protocol::curve::make_keypair(), {}}, {}};
  for (const auto& name : names) {
    const protocol::curve::ClientKeys peer{keys.server.own.public_key, protocol::curve::make_keypair()};
    keys.server.participants.emplace(peer.own.public_key, name);
    keys.peers.emplace(name, peer);
  }
  return keys;
}

}  // namespace cosim::bench
