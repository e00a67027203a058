#include "tracker/program/stage_times.hpp"

#include "coupler/participant/stage_summary.hpp"

namespace cosim::tracker {

std::string StageTimes::summary() const { return participant::stage_summary(kStageNames, seconds_); }

}  // namespace cosim::tracker
