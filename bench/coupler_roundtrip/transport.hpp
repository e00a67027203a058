// Where the benchmark's server listens.
#pragma once

#include <string>

namespace cosim::bench {

enum class Transport { Ipc, Tcp };

const char* to_string(Transport t);
// A fresh address to bind: a socket file in a temporary folder, or a free loopback port.
std::string bind_address(Transport t);

}  // namespace cosim::bench
