// The stages of a World substep in the order World::advance runs them, and the wall seconds
// each took over a window (StepReport::seconds), as Box2D's b2Profile reports its step:
// where a step's time goes without a profiler.
#pragma once

#include <array>
#include <chrono>
#include <cstddef>

namespace cosim::world {

enum class Stage { integrate_velocities, broad_phase, narrow_phase, solve_contacts, integrate_positions, relax_contacts };
inline constexpr std::array kStageNames{"integrate velocities", "broad phase",         "narrow phase",
                                        "solve contacts",       "integrate positions", "relax contacts"};

class StageSeconds {
 public:
  double& operator[](Stage stage) { return seconds_[static_cast<std::size_t>(stage)]; }
  double operator[](Stage stage) const { return seconds_[static_cast<std::size_t>(stage)]; }
  StageSeconds& operator+=(const StageSeconds& other) {
    for (std::size_t s = 0; s < seconds_.size(); ++s) seconds_[s] += other.seconds_[s];
    return *this;
  }
  const std::array<double, kStageNames.size()>& all() const { return seconds_; }  // in kStageNames' order

 private:
  std::array<double, kStageNames.size()> seconds_{};
};

// Times stages that run one after the other: lap(stage) after each adds the time since the
// previous lap (or the clock's start) to that stage. One clock read per stage.
class StageClock {
 public:
  explicit StageClock(StageSeconds& seconds) : seconds_(seconds) {}
  void lap(Stage stage) {
    const auto now = std::chrono::steady_clock::now();
    seconds_[stage] += std::chrono::duration<double>(now - last_).count();
    last_ = now;
  }

 private:
  StageSeconds& seconds_;
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

}  // namespace cosim::world
