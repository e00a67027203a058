#include "tests/integration/network_namespaces.hpp"

#include <unistd.h>

#include <cstdlib>

namespace cosim::testing {
namespace {

int sh(const std::string& command) { return std::system((command + " >/dev/null 2>&1").c_str()); }

}  // namespace

std::string NamespacePair::path(const std::string& name) { return "/var/run/netns/" + name; }

NamespacePair::NamespacePair() {
  if (geteuid() != 0) {
    why_ = "not root: making network namespaces needs CAP_NET_ADMIN";
    return;
  }
  const std::string id = std::to_string(getpid());
  const std::string a = "cosim-a-" + id, b = "cosim-b-" + id,
                    veth = "cv" + id.substr(id.size() > 8 ? id.size() - 8 : 0);
  // Left behind by a test process of the same pid that was killed.
  sh("ip netns del " + a);
  sh("ip netns del " + b);
  if (sh("ip netns add " + a) != 0) {
    why_ = "`ip netns add` failed: this machine (a container without CAP_NET_ADMIN?) cannot make network namespaces";
    return;
  }
  const bool ok = sh("ip netns add " + b) == 0 &&
                  sh("ip link add " + veth + "a netns " + a + " type veth peer name " + veth + "b netns " + b) == 0 &&
                  sh("ip -n " + a + " addr add " + std::string(kFirstAddress) + "/24 dev " + veth + "a") == 0 &&
                  sh("ip -n " + b + " addr add " + std::string(kSecondAddress) + "/24 dev " + veth + "b") == 0 &&
                  sh("ip -n " + a + " link set " + veth + "a up") == 0 &&
                  sh("ip -n " + b + " link set " + veth + "b up") == 0 && sh("ip -n " + a + " link set lo up") == 0 &&
                  sh("ip -n " + b + " link set lo up") == 0;
  if (!ok) {
    sh("ip netns del " + a);
    sh("ip netns del " + b);
    why_ = "the veth pair between the namespaces could not be made";
    return;
  }
  first_ = a;
  second_ = b;
  link_ = veth + "b";
}

NamespacePair::~NamespacePair() {
  if (!made()) return;
  sh("ip netns del " + first_);
  sh("ip netns del " + second_);
}

int NamespacePair::in_second(const std::string& command) const {
  std::string line = command;
  for (std::size_t at = line.find("LINK"); at != std::string::npos; at = line.find("LINK", at))
    line.replace(at, 4, link_);
  return sh("ip netns exec " + second_ + " " + line);
}

}  // namespace cosim::testing
