// Two hosts on one machine: two network namespaces joined by a veth pair, 10.231.0.1 in
// the first and 10.231.0.2 in the second (each pair sees only its own link, so parallel
// tests may use the same addresses). Needs root (CAP_NET_ADMIN) and `ip` from iproute2;
// `available()` says why not where the machine cannot make them.
#pragma once

#include <string>

namespace cosim::testing {

class NamespacePair {
 public:
  static constexpr const char* kFirstAddress = "10.231.0.1";
  static constexpr const char* kSecondAddress = "10.231.0.2";

  NamespacePair();   // empty names if it could not be made: see why()
  ~NamespacePair();  // deletes both namespaces, and the link with them
  NamespacePair(const NamespacePair&) = delete;
  NamespacePair& operator=(const NamespacePair&) = delete;

  bool made() const { return !first_.empty(); }
  const std::string& why() const { return why_; }
  const std::string& first() const { return first_; }    // the coupler's host
  const std::string& second() const { return second_; }  // the participant's host
  // Runs a command inside the second namespace (`ip link set LINK down`, `tc qdisc ...`),
  // LINK replaced by its end of the link; returns its exit status.
  int in_second(const std::string& command) const;
  // The /var/run/netns path of a namespace, for setns().
  static std::string path(const std::string& name);

 private:
  std::string first_, second_, link_, why_;
};

}  // namespace cosim::testing
