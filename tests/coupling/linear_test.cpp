// Linear problems x = A x + b, where the answer (I - A)^{-1} b is known and IQN-ILS has an
// exact finite-termination property to check.
#include <gtest/gtest.h>

#include "tests/coupling/problems.hpp"

namespace cosim::coupling::test {
namespace {

constexpr double solution_tolerance = 1e-10;

double error(const Window& window, const Problem& problem) { return (window.x() - problem.solution).norm(); }

TEST(Linear, ContractiveAllConvergeAndAcceleratedNeedFewer) {
  const Eigen::Index n = 8;
  const Problem problem = linear(Eigen::VectorXd::LinSpaced(n, -0.5, 0.5), 11);
  const Eigen::VectorXd x0 = Eigen::VectorXd::Zero(n);
  const double w = 0.5;
  const Window fixed = iterate(*make_fixed_point(), problem, x0, 200);
  const Window constant = iterate(*make_constant(w), problem, x0, 200);
  const Window aitken = iterate(*make_aitken(w), problem, x0, 200);
  const Window iqn = iterate(*make_iqn_ils(w), problem, x0, 200);
  report("linear contractive n=8, rho=0.5, w=0.5",
         {{"fixed_point", fixed}, {"constant", constant}, {"aitken", aitken}, {"iqn_ils", iqn}});

  for (const Window* window : {&fixed, &constant, &aitken, &iqn}) {
    EXPECT_TRUE(window->converged);
    EXPECT_LT(error(*window, problem), solution_tolerance);
  }
  EXPECT_LT(aitken.updates, constant.updates);
  EXPECT_LT(iqn.updates, constant.updates);
  EXPECT_LE(iqn.updates, n + 1);
}

// Eigenvalues in [-3, -1]: the sign and size of an added-mass instability, where each pass
// overshoots by up to three times the error.
class NonContractive : public ::testing::TestWithParam<int> {};

TEST_P(NonContractive, OnlyRelaxedAndAcceleratedConverge) {
  const Eigen::Index n = GetParam();
  const Problem problem = linear(Eigen::VectorXd::LinSpaced(n, -3.0, -1.0), 100 + GetParam());
  const Eigen::VectorXd x0 = Eigen::VectorXd::Zero(n);
  // Relaxed iteration matrix (1 - w) I + w A has eigenvalues 1 - w (1 - lambda), which lie
  // in (-1, 1) only for w < 2 / 4: 0.1 is safely inside, and slow.
  const double w = 0.1;
  const Window fixed = iterate(*make_fixed_point(), problem, x0, 30);
  const Window constant = iterate(*make_constant(w), problem, x0, 1000);
  const Window aitken = iterate(*make_aitken(w), problem, x0, 1000);
  const Window iqn = iterate(*make_iqn_ils(w), problem, x0, 1000);
  report("linear rho=3 n=" + std::to_string(n) + ", w=0.1",
         {{"fixed_point", fixed}, {"constant", constant}, {"aitken", aitken}, {"iqn_ils", iqn}});

  // x_0 = 0, so |x*| is the error it started from.
  EXPECT_FALSE(fixed.converged);
  EXPECT_GT(error(fixed, problem), 1e6 * problem.solution.norm());
  for (const Window* window : {&constant, &aitken, &iqn}) {
    EXPECT_TRUE(window->converged);
    EXPECT_LT(error(*window, problem), solution_tolerance);
  }
  // Exact for a linear problem: once x_0 .. x_n are evaluated V has n independent columns,
  // so the next step is Newton's and x_{n+1} is the solution.
  EXPECT_LE(iqn.updates, n + 1);
  EXPECT_LT(aitken.updates, constant.updates);
}

INSTANTIATE_TEST_SUITE_P(Dimensions, NonContractive, ::testing::Range(5, 11));

}  // namespace
}  // namespace cosim::coupling::test
