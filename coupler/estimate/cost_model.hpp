// One program's cost model: a step costs a constant plus a coefficient times each count it
// grows with (cells, markers, bodies, particles), and its memory a base plus bytes per count
// held. The coefficients are fitted to what runs on this machine measured, pulled towards a
// prior where the runs do not tell them apart.
#pragma once

#include <string>
#include <vector>

#include "coupler/estimate/work.hpp"

namespace cosim::estimate {

// One finished run of one program: what its steps held and what they took.
struct Observation {
  Units per_step;
  Units held;
  double steps = 0;       // its steps over the run, every coupling iteration's counted
  double seconds = 0;     // its wall seconds inside those steps
  double peak_bytes = 0;  // the peak resident set of its largest process; 0: not measured
};

struct Coefficients {
  double seconds_per_step = 0;  // what a step costs whatever it holds
  Units seconds_per_unit;       // per step and per count
  double base_bytes = 0;
  Units bytes_per_unit;
};

double step_seconds(const Coefficients& c, const Units& per_step);
double memory_bytes(const Coefficients& c, const Units& held);

// Non-negative least squares in the relative error of each observation, with one row per
// prior coefficient (its relative change) weighted by `prior_weight`: small, so that it only
// decides what the observations leave open. With no observations the prior comes back; with
// one, the prior changed least to meet it; with several of different sizes, the measurements alone.
Coefficients fit(const std::vector<Observation>& observations, const Coefficients& prior, double prior_weight = 1e-3);

}  // namespace cosim::estimate
