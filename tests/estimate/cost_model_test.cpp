#include "coupler/estimate/cost_model.hpp"

#include <gtest/gtest.h>

#include <random>

namespace cosim::estimate {
namespace {

// A program whose step costs 1 ms + 2e-7 s per cell + 3e-5 s per marker, and whose memory is
// 50 MB + 500 B per cell, measured with 5 % noise at sizes a calibration would run.
std::vector<Observation> measured(std::size_t n, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> noise(0.95, 1.05), cells(1e3, 1e6), markers(0, 5e3);
  std::vector<Observation> out;
  for (std::size_t i = 0; i < n; ++i) {
    Observation o;
    o.per_step = {{"cells", cells(random)}, {"markers", markers(random)}};
    o.held = o.per_step;
    o.steps = 100;
    o.seconds = o.steps * (1e-3 + 2e-7 * o.per_step["cells"] + 3e-5 * o.per_step["markers"]) * noise(random);
    o.peak_bytes = (50e6 + 500 * o.held["cells"]) * noise(random);
    out.push_back(o);
  }
  return out;
}

const Coefficients kWrongPrior{3e-3, {{"cells", 6e-7}, {"markers", 1e-5}}, 150e6, {{"cells", 1500}, {"markers", 0}}};

TEST(CostModel, WithoutMeasurementsThePriorComesBack) {
  const Coefficients c = fit({}, kWrongPrior);
  EXPECT_DOUBLE_EQ(c.seconds_per_step, 3e-3);
  EXPECT_NEAR(c.seconds_per_unit.at("cells"), 6e-7, 1e-20);
  EXPECT_NEAR(c.bytes_per_unit.at("cells"), 1500, 1e-9);
}

TEST(CostModel, MeasurementsOfDifferentSizesRecoverTheCoefficients) {
  const Coefficients c = fit(measured(12, 1), kWrongPrior);
  EXPECT_NEAR(c.seconds_per_unit.at("cells"), 2e-7, 0.15 * 2e-7);
  EXPECT_NEAR(c.seconds_per_unit.at("markers"), 3e-5, 0.15 * 3e-5);
  EXPECT_NEAR(c.bytes_per_unit.at("cells"), 500, 0.15 * 500);
  // Predictions at sizes none of them had, within the noise.
  const Units big{{"cells", 4e6}, {"markers", 2e4}};
  EXPECT_NEAR(step_seconds(c, big), 1e-3 + 0.8 + 0.6, 0.1 * 1.4);
  EXPECT_NEAR(memory_bytes(c, big), 50e6 + 2e9, 0.1 * 2.05e9);
}

TEST(CostModel, CoefficientsStayNonNegative) {
  // Timings that fall with the cells (a warm cache) would give a negative coefficient.
  std::vector<Observation> obs;
  for (double cells : {1e3, 1e4, 1e5}) obs.push_back({{{"cells", cells}}, {}, 10, 10 * (0.02 - 1e-8 * cells), 0});
  const Coefficients c = fit(obs, kWrongPrior);
  EXPECT_GE(c.seconds_per_step, 0);
  for (const auto& [unit, s] : c.seconds_per_unit) EXPECT_GE(s, 0) << unit;
  // A constant alone still meets every timing within the 5 % they fall by.
  for (const Observation& o : obs)
    EXPECT_NEAR(step_seconds(c, o.per_step), o.seconds / o.steps, 0.05 * o.seconds / o.steps);
}

TEST(CostModel, OneSizeMeasuredScalesThePriorTowardsIt) {
  // A single run cannot tell the coefficients apart; its step's cost is still met closely.
  std::vector<Observation> one{{{{"cells", 1e5}, {"markers", 0}}, {}, 100, 100 * 0.021, 0}};
  const Coefficients c = fit(one, kWrongPrior);
  EXPECT_NEAR(step_seconds(c, {{"cells", 1e5}}), 0.021, 0.15 * 0.021);
}

}  // namespace
}  // namespace cosim::estimate
