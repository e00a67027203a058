// One line on stderr, rewritten in place as a standalone run's windows go (as `cosim run`
// shows its windows), only on a terminal so logs and tests stay clean.
#pragma once

#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>

namespace cosim::participant {

class Progress {
 public:
  Progress(std::uint64_t windows, double end_time)
      : windows_(windows), end_(end_time), enabled_(isatty(STDERR_FILENO)) {}

  // After `window` of the windows, at `time`; `extra` (if any) follows the window count.
  void update(std::uint64_t window, double time, const std::string& extra) {
    const auto now = clock::now();
    if (!enabled_ || (window != windows_ && now - last_ < std::chrono::milliseconds(100))) return;
    last_ = now;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double rate = elapsed > 0 ? static_cast<double>(window) / elapsed : 0.0;
    std::fprintf(stderr, "\r  t = %.4g / %.4g s  window %llu/%llu  %s%s%.1f windows/s  ETA %.0f s   ", time, end_,
                 static_cast<unsigned long long>(window), static_cast<unsigned long long>(windows_), extra.c_str(),
                 extra.empty() ? "" : "  ", rate, rate > 0 ? static_cast<double>(windows_ - window) / rate : 0.0);
    printed_ = true;
  }
  void finish() {
    if (printed_) std::fputc('\n', stderr);
    printed_ = false;
  }

 private:
  using clock = std::chrono::steady_clock;
  std::uint64_t windows_;
  double end_;
  bool enabled_;
  bool printed_ = false;
  clock::time_point start_ = clock::now(), last_{};
};

}  // namespace cosim::participant
