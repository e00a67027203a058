#include "transport.hpp"

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

const char* to_string(Transport t) { return t == Transport::Ipc ? "ipc" : "tcp"; }

std::string bind_address(Transport t) {
  static SocketFolder folder;
  return t == Transport::Ipc ? "ipc://" + folder.next() : "tcp://127.0.0.1:0";
}

}  // namespace cosim::bench
