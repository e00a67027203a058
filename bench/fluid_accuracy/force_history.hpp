// A force coefficient history split into its smooth part and the high-frequency rest that
// the staircase FBM adds (faces switching between solid and fluid).
#pragma once

#include <vector>

#include "bench/fluid_accuracy/oscillating.hpp"

namespace cosim::bench {

// The smooth part at every sample: a least-squares quadratic in time through the samples
// within window / 2 of it (fewer at the ends of the history), evaluated there. A quadratic,
// not a moving average, so the smooth part keeps its peaks: with the window a twentieth of
// the period it follows a sinusoid of that period to 2e-6 of its amplitude (the bias is
// h^4 f/280 for h = window / 2) away from the ends.
std::vector<double> smoothed(const std::vector<double>& time, const std::vector<double>& value, double window);

struct Spurious {
  double rms = 0, max = 0;  // of value - smoothed over the interval
};

struct ForceSummary {
  double mean_drag = 0, mean_lift = 0;  // time averages (each sample weighted by its step)
  double peak_drag = 0;                 // max |smooth drag|
  Spurious drag, lift;
};

// Over the samples with time > from.
ForceSummary summarise(const std::vector<ForceSample>& history, double from, double window);

}  // namespace cosim::bench
