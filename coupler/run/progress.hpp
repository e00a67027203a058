// One status line on the terminal while a run goes: simulated time, windows per second,
// ETA and mean coupling iterations. Silent when stderr is not a terminal (logs, CI).
#pragma once

#include <chrono>
#include <cstdint>

namespace cosim::run {

class Progress {
 public:
  Progress(std::uint64_t first_window, std::uint64_t windows, double end_time, bool enabled);
  void update(std::uint64_t window, double time, int iterations);
  void finish();  // ends the line so later output starts on a fresh one

 private:
  using clock = std::chrono::steady_clock;
  std::uint64_t first_, windows_;
  double end_time_;
  bool enabled_;
  clock::time_point start_ = clock::now(), last_print_{};
  std::uint64_t iterations_ = 0;
  bool printed_ = false;
};

}  // namespace cosim::run
