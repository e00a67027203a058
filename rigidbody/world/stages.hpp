// The stages of a World substep in the order World::advance runs them, and the wall seconds
// each took over a window (StepReport::seconds, timing/stage_seconds.hpp).
#pragma once

#include <array>

#include "timing/stage_seconds.hpp"

namespace cosim::rigidbody::world {

enum class Stage {
  integrate_velocities,
  broad_phase,
  narrow_phase,
  solve_contacts,
  integrate_positions,
  relax_contacts
};
inline constexpr std::array kStageNames{"integrate velocities", "broad phase",         "narrow phase",
                                        "solve contacts",       "integrate positions", "relax contacts"};

using StageSeconds = timing::StageSeconds<Stage, kStageNames.size()>;
using StageClock = timing::StageClock<StageSeconds>;

}  // namespace cosim::rigidbody::world
