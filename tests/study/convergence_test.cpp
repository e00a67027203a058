// The three-level estimate against the worked example of Celik et al., J. Fluids Eng. 130
// (2008) 078001, Table 1, and against manufactured sequences phi = phi0 + C h^p.
#include <gtest/gtest.h>

#include <cmath>

#include "coupler/study/convergence.hpp"

namespace cosim::study {
namespace {

// Table 1's grids: N cells in 2-d, h = (1 / N)^(1/2), so r = sqrt(N_fine / N_coarse).
double ratio(double fine_cells, double coarse_cells) { return std::sqrt(fine_cells / coarse_cells); }

// Column 1: the reattachment length, grids of 18000, 8000 and 4500 cells. The table gives
// p = 1.53, phi_ext = 6.1685, e_a = 1.5 %, e_ext = 1.7 %, GCI_fine = 2.17 %.
TEST(Celik, MonotonicReattachmentLength) {
  const Estimate e = estimate(6.063, 5.972, 5.863, ratio(18000, 8000), ratio(8000, 4500));
  EXPECT_EQ(e.convergence, Convergence::Monotonic);
  ASSERT_TRUE(e.order);
  EXPECT_NEAR(*e.order, 1.53, 0.005);
  EXPECT_NEAR(e.extrapolate, 6.1685, 0.00005);
  EXPECT_NEAR(100 * e.e_a21, 1.5, 0.05);
  EXPECT_NEAR(100 * e.e_ext21, 1.7, 0.05);
  EXPECT_NEAR(100 * e.gci_fine, 2.17, 0.005);
  EXPECT_NEAR(e.gci_fine_abs, e.gci_fine * 6.063, 1e-12);
}

// Column 2: an axial velocity, grids of 18000, 4500 and 980 cells (r21 = 2, r32 = 2.143).
// The table gives p = 0.75, phi_ext = 10.8801, e_a = 0.6 %, e_ext = 0.8 %, GCI_fine = 1.1 %.
TEST(Celik, MonotonicLowOrder) {
  const Estimate e = estimate(10.7880, 10.7250, 10.6050, ratio(18000, 4500), ratio(4500, 980));
  EXPECT_EQ(e.convergence, Convergence::Monotonic);
  ASSERT_TRUE(e.order);
  EXPECT_NEAR(*e.order, 0.75, 0.005);
  EXPECT_NEAR(e.extrapolate, 10.8801, 0.00005);
  EXPECT_NEAR(100 * e.e_a21, 0.6, 0.05);
  EXPECT_NEAR(100 * e.e_ext21, 0.85, 0.05);
  EXPECT_NEAR(100 * e.gci_fine, 1.1, 0.05);
}

// Column 3: another axial velocity on the same grids, with oscillatory convergence. The
// table gives p = 1.5, phi_ext = 6.0269, e_a = 0.7 %, e_ext = 0.38 %, GCI_fine = 0.47 %.
TEST(Celik, Oscillatory) {
  const Estimate e = estimate(6.0042, 5.9624, 6.0909, ratio(18000, 4500), ratio(4500, 980));
  EXPECT_EQ(e.convergence, Convergence::Oscillatory);
  ASSERT_TRUE(e.order);
  EXPECT_NEAR(*e.order, 1.5, 0.01);
  EXPECT_NEAR(e.extrapolate, 6.0269, 0.00005);
  EXPECT_NEAR(100 * e.e_a21, 0.7, 0.05);
  EXPECT_NEAR(100 * e.e_ext21, 0.38, 0.005);
  EXPECT_NEAR(100 * e.gci_fine, 0.47, 0.005);
}

// phi = phi0 + C h^p on h = 1, 0.6, 0.25: unequal ratios 1/0.6 and 0.6/0.25.
TEST(Manufactured, UnequalRatiosGiveBackOrderAndLimit) {
  for (const double p : {0.8, 1.0, 2.0, 3.5}) {
    const double phi0 = 3.0, c = -0.7;
    const auto phi = [&](double h) { return phi0 + c * std::pow(h, p); };
    const Estimate e = estimate(phi(0.25), phi(0.6), phi(1.0), 0.6 / 0.25, 1.0 / 0.6);
    EXPECT_EQ(e.convergence, Convergence::Monotonic) << p;
    ASSERT_TRUE(e.order) << p;
    EXPECT_NEAR(*e.order, p, 1e-9) << p;
    EXPECT_NEAR(e.extrapolate, phi0, 1e-12) << p;
    // The GCI bounds the fine level's true error with the factor of safety 1.25.
    EXPECT_NEAR(e.gci_fine_abs, 1.25 * std::abs(phi(0.25) - phi0), 1e-12) << p;
  }
}

// phi = phi0 + C (-1)^i h_i^p: each level on the other side of the limit. The paper's
// iteration gives p back; its extrapolate assumes monotonic convergence and misses phi0.
TEST(Manufactured, OscillatingSequenceIsNamedAndGivesBackItsOrder) {
  const double phi0 = 1.0, c = 0.2, p = 2.0;
  const auto phi = [&](double h, double sign) { return phi0 + sign * c * std::pow(h, p); };
  const Estimate e = estimate(phi(0.2, 1), phi(0.5, -1), phi(1.0, 1), 2.5, 2.0);
  EXPECT_EQ(e.convergence, Convergence::Oscillatory);
  ASSERT_TRUE(e.order);
  EXPECT_NEAR(*e.order, p, 1e-9);
}

// The paper's absolute value would give a positive p to levels that move apart.
TEST(Manufactured, LevelsMovingApartAreDivergingWithoutAnOrder) {
  const Estimate e = estimate(1.4, 1.2, 1.1, 2, 2);  // the fine pair differs twice as much
  EXPECT_EQ(e.convergence, Convergence::Diverging);
  EXPECT_FALSE(e.order);
  EXPECT_EQ(e.extrapolate, 1.4);
  // With unequal ratios the threshold is |e32 / e21| = ln r32 / ln r21, p = 0: a ratio of
  // differences of 0.9 converges for r21 = 2, r32 = 1.5 (threshold 0.585) ...
  EXPECT_EQ(estimate(1.0, 1.1, 1.19, 2, 1.5).convergence, Convergence::Monotonic);
  // ... and diverges for r21 = 1.5, r32 = 2 (threshold 1.71).
  EXPECT_EQ(estimate(1.0, 1.1, 1.19, 1.5, 2).convergence, Convergence::Diverging);
  EXPECT_EQ(estimate(1.0, 1.1, 1.1, 2, 2).convergence, Convergence::Diverging);
}

TEST(Manufactured, EqualFineLevelsAreUnchanged) {
  const Estimate e = estimate(2.0, 2.0, 1.5, 2, 2);
  EXPECT_EQ(e.convergence, Convergence::Unchanged);
  EXPECT_FALSE(e.order);
  EXPECT_EQ(e.extrapolate, 2.0);
}

}  // namespace
}  // namespace cosim::study
