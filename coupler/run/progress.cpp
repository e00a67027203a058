#include "coupler/run/progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace cosim::run {

Progress::Progress(std::uint64_t first_window, std::uint64_t windows, double end_time, bool enabled)
    : first_(first_window), windows_(windows), end_time_(end_time), enabled_(enabled && isatty(STDERR_FILENO)) {}

void Progress::update(std::uint64_t window, double time, int iterations) {
  iterations_ += static_cast<std::uint64_t>(iterations);
  const auto now = clock::now();
  const bool last = window + 1 == windows_;
  if (!enabled_ || (!last && now - last_print_ < std::chrono::milliseconds(100))) return;
  last_print_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double done = static_cast<double>(window + 1 - first_);
  const double rate = elapsed > 0 ? done / elapsed : 0.0;
  const double eta = rate > 0 ? static_cast<double>(windows_ - window - 1) / rate : 0.0;
  std::fprintf(stderr, "\r  t = %.4g / %.4g s  window %llu/%llu  %.1f windows/s  ETA %.0f s  %.2f it/window   ", time,
               end_time_, static_cast<unsigned long long>(window + 1), static_cast<unsigned long long>(windows_), rate,
               eta, static_cast<double>(iterations_) / done);
  printed_ = true;
}

void Progress::finish() {
  if (printed_) std::fputc('\n', stderr);
  printed_ = false;
}

}  // namespace cosim::run
