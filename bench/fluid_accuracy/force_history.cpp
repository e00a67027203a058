#include "bench/fluid_accuracy/force_history.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace cosim::bench {

std::vector<double> smoothed(const std::vector<double>& time, const std::vector<double>& value, double window) {
  std::vector<double> out(time.size());
  std::size_t lo = 0, hi = 0;  // the samples within window / 2 of sample i: [lo, hi)
  for (std::size_t i = 0; i < time.size(); ++i) {
    while (time[lo] < time[i] - window / 2) ++lo;
    while (hi < time.size() && time[hi] <= time[i] + window / 2) ++hi;
    // Normal equations in s = (t - t_i) / window, which keeps them well conditioned.
    Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
    Eigen::Vector3d b = Eigen::Vector3d::Zero();
    for (std::size_t j = lo; j < hi; ++j) {
      const double s = (time[j] - time[i]) / window;
      const Eigen::Vector3d basis(1, s, s * s);
      a += basis * basis.transpose();
      b += basis * value[j];
    }
    out[i] = hi - lo >= 3 ? a.ldlt().solve(b)[0] : value[i];
  }
  return out;
}

namespace {

Spurious spurious(const std::vector<double>& time, const std::vector<double>& value, const std::vector<double>& smooth,
                  double from) {
  Spurious s;
  int n = 0;
  for (std::size_t i = 0; i < time.size(); ++i)
    if (time[i] > from) {
      const double r = value[i] - smooth[i];
      s.rms += r * r;
      s.max = std::max(s.max, std::abs(r));
      ++n;
    }
  s.rms = n > 0 ? std::sqrt(s.rms / n) : 0;
  return s;
}

}  // namespace

ForceSummary summarise(const std::vector<ForceSample>& history, double from, double window) {
  std::vector<double> time, drag, lift;
  for (const ForceSample& f : history) {
    time.push_back(f.time);
    drag.push_back(f.drag);
    lift.push_back(f.lift);
  }
  ForceSummary out;
  double span = 0;
  for (std::size_t i = 1; i < history.size(); ++i)
    if (time[i] > from) {
      const double dt = time[i] - std::max(time[i - 1], from);
      out.mean_drag += dt * drag[i];
      out.mean_lift += dt * lift[i];
      span += dt;
    }
  if (span > 0) {
    out.mean_drag /= span;
    out.mean_lift /= span;
  }
  const std::vector<double> smooth_drag = smoothed(time, drag, window);
  for (std::size_t i = 0; i < time.size(); ++i)
    if (time[i] > from) out.peak_drag = std::max(out.peak_drag, std::abs(smooth_drag[i]));
  out.drag = spurious(time, drag, smooth_drag, from);
  out.lift = spurious(time, lift, smoothed(time, lift, window), from);
  return out;
}

}  // namespace cosim::bench
