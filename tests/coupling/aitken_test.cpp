// Aitken's properties that the multi-dimensional comparisons cannot show.
#include <gtest/gtest.h>

#include "tests/coupling/problems.hpp"

namespace cosim::coupling::test {
namespace {

// In one dimension Aitken's factor after one step is the exact inverse slope 1 / (1 - a),
// so x_2 is the solution: two updates, three evaluations of H (the last only confirms).
class ScalarAitken : public ::testing::TestWithParam<double> {};

TEST_P(ScalarAitken, ConvergesInTwoUpdates) {
  const double a = GetParam();
  const Problem problem = linear(Eigen::VectorXd::Constant(1, a), 7);
  const Window window = iterate(*make_aitken(0.1), problem, Eigen::VectorXd::Zero(1), 10);
  report("scalar linear a=" + ::testing::PrintToString(a), {{"aitken", window}});
  EXPECT_TRUE(window.converged);
  EXPECT_LE(window.updates, 2);
  EXPECT_LT((window.x() - problem.solution).norm(), 1e-10);
}

INSTANTIATE_TEST_SUITE_P(Slopes, ScalarAitken, ::testing::Values(0.5, -0.5, -3.0, -10.0));

// The same (x, H(x)) twice gives r_k = r_{k-1}, a 0/0 factor: the last factor must stay,
// and the window must go on to converge.
TEST(Aitken, UnchangedResidualKeepsTheFactor) {
  const Problem problem = linear(Eigen::VectorXd::LinSpaced(4, -3.0, -1.0), 8);
  const auto aitken = make_aitken(0.1);
  const Eigen::VectorXd x0 = Eigen::VectorXd::Zero(4);
  const Eigen::VectorXd hx0 = problem.h(x0);
  const Eigen::VectorXd x1 = aitken->next(x0, hx0);
  EXPECT_TRUE(aitken->next(x0, hx0).isApprox(x1, 1e-15));

  Eigen::VectorXd x = x1;
  for (int k = 0; k < 100 && (problem.h(x) - x).norm() > residual_tolerance; ++k) {
    x = aitken->next(x, problem.h(x));
  }
  EXPECT_LT((x - problem.solution).norm(), 1e-10);
}

}  // namespace
}  // namespace cosim::coupling::test
