// Bounds the smoke test enforces: a benchmark that cannot fail would not notice a solver
// that broke.
#pragma once

#include <string>
#include <vector>

#include "bench/rigidbody_accuracy/run.hpp"

namespace cosim::bench {

// One message per violated bound; empty when all hold.
std::vector<std::string> sanity_failures(const std::vector<Run>& runs);

}  // namespace cosim::bench
