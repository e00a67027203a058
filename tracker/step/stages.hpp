// The stages of the tracker's step in the order Simulation::step runs them, and the wall
// seconds each took, summed over the steps since the start (timing/stage_seconds.hpp):
// cosim-tracker prints them, bench READMEs quote them.
#pragma once

#include <array>

#include "timing/stage_seconds.hpp"

namespace cosim::tracker::step {

enum class Stage { migrate, sort, collide, move, inject, hand_over, sample };
inline constexpr std::array kStageNames{"migrate", "sort", "collide", "move", "inject", "hand-over", "sample"};

using StageSeconds = timing::StageSeconds<Stage, kStageNames.size()>;

}  // namespace cosim::tracker::step
