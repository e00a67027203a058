// Where the benchmark's server listens.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "coupler/protocol/curve.hpp"

namespace cosim::bench {

// Curve: tcp on 127.0.0.2 with CURVE, as `cosim run` listens on coupling.interface.
enum class Transport { Ipc, Tcp, Curve };

const char* to_string(Transport t);
// A fresh address to bind: a socket file in a temporary folder, or a free loopback port.
std::string bind_address(Transport t);

// The Curve transport's keys: the server's, and a pair for each peer by name.
struct Keys {
  protocol::curve::ServerKeys server;
  std::map<std::string, protocol::curve::ClientKeys> peers;
};
Keys make_keys(const std::vector<std::string>& names);

}  // namespace cosim::bench
