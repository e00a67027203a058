// Wall seconds per stage of the tracker's step, summed over the steps since the start: what
// each stage of a run costs (cosim-tracker prints them; bench READMEs quote them).
#pragma once

#include <array>
#include <chrono>
#include <cstddef>

namespace cosim::tracker {

enum class Stage { migrate, sort, collide, move, inject, hand_over, sample };
inline constexpr std::array kStageNames{"migrate", "sort", "collide", "move", "inject", "hand-over", "sample"};

class StageTimes {
 public:
  // Runs f and adds its wall time to the stage's.
  template <class F>
  void time(Stage stage, F&& f) {
    const auto start = std::chrono::steady_clock::now();
    f();
    const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
    seconds_[static_cast<std::size_t>(stage)] += took.count();
  }
  double seconds(Stage stage) const { return seconds_[static_cast<std::size_t>(stage)]; }
  const std::array<double, kStageNames.size()>& all() const { return seconds_; }  // in kStageNames' order

 private:
  std::array<double, kStageNames.size()> seconds_{};
};

}  // namespace cosim::tracker
