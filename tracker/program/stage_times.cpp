#include "tracker/program/stage_times.hpp"

#include <cstdio>

namespace cosim::tracker {

std::string StageTimes::summary() const {
  std::string out;
  for (std::size_t s = 0; s < kStageNames.size(); ++s) {
    if (seconds_[s] == 0.0) continue;
    char text[64];
    std::snprintf(text, sizeof text, "%s%s %.2f s", out.empty() ? "" : ", ", kStageNames[s], seconds_[s]);
    out += text;
  }
  return out;
}

}  // namespace cosim::tracker
