// Wall seconds per stage of a program's step, as Box2D's b2Profile reports its step: where
// a step's time goes without a profiler. Each program names its stages (an enum and
// kStageNames in the order its step runs them) and keeps one StageSeconds of them.
#pragma once

#include <array>
#include <chrono>
#include <cstddef>

namespace cosim::timing {

template <class Stage, std::size_t N>
class StageSeconds {
 public:
  double& operator[](Stage stage) { return seconds_[static_cast<std::size_t>(stage)]; }
  double operator[](Stage stage) const { return seconds_[static_cast<std::size_t>(stage)]; }
  StageSeconds& operator+=(const StageSeconds& other) {
    for (std::size_t s = 0; s < N; ++s) seconds_[s] += other.seconds_[s];
    return *this;
  }
  const std::array<double, N>& all() const { return seconds_; }  // in the order of the stages' names

  // Runs f and adds its wall time to the stage's.
  template <class F>
  void time(Stage stage, F&& f) {
    const auto start = std::chrono::steady_clock::now();
    f();
    (*this)[stage] += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

 private:
  std::array<double, N> seconds_{};
};

// Times stages that run one after the other: lap(stage) after each adds the time since the
// previous lap (or the clock's start) to that stage. One clock read per stage.
template <class Seconds>
class StageClock {
 public:
  explicit StageClock(Seconds& seconds) : seconds_(seconds) {}
  template <class Stage>
  void lap(Stage stage) {
    const auto now = std::chrono::steady_clock::now();
    seconds_[stage] += std::chrono::duration<double>(now - last_).count();
    last_ = now;
  }

 private:
  Seconds& seconds_;
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

}  // namespace cosim::timing
