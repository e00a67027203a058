// The seconds of a program's step stages as one line, for the summary a program prints at
// the end of a standalone run (cosim-fluid, cosim-rigidbody, cosim-tracker).
#pragma once

#include <array>
#include <cstddef>
#include <cstdio>
#include <string>

namespace cosim::participant {

// "migrate 0.12 s, sort 0.80 s, ...": the stages that took any time, in their order.
template <std::size_t N>
std::string stage_summary(const std::array<const char*, N>& names, const std::array<double, N>& seconds) {
  std::string out;
  for (std::size_t s = 0; s < N; ++s) {
    if (seconds[s] == 0.0) continue;
    char text[64];
    std::snprintf(text, sizeof text, "%s%s %.2f s", out.empty() ? "" : ", ", names[s], seconds[s]);
    out += text;
  }
  return out;
}

}  // namespace cosim::participant
