// A nonlinear problem, H(x) = b - c tanh(x), unstable for plain iteration near 0.
#include <gtest/gtest.h>

#include "tests/coupling/problems.hpp"

namespace cosim::coupling::test {
namespace {

TEST(Nonlinear, TanhConvergesWithAitkenAndIqnIls) {
  const Eigen::Index n = 6;
  const double c = 3.0;
  const Problem problem = tanh_problem(Eigen::VectorXd::LinSpaced(n, -2.0, 2.0), c);
  const Eigen::VectorXd x0 = Eigen::VectorXd::Zero(n);
  const double w = 0.1;
  const Window fixed = iterate(*make_fixed_point(), problem, x0, 200);
  const Window constant = iterate(*make_constant(w), problem, x0, 1000);
  const Window aitken = iterate(*make_aitken(w), problem, x0, 200);
  const Window iqn = iterate(*make_iqn_ils(w), problem, x0, 200);
  report("tanh n=6, c=3, w=0.1",
         {{"fixed_point", fixed}, {"constant", constant}, {"aitken", aitken}, {"iqn_ils", iqn}});

  EXPECT_FALSE(fixed.converged);
  for (const Window* window : {&aitken, &iqn}) {
    EXPECT_TRUE(window->converged);
    EXPECT_LT((window->x() - problem.solution).norm(), 1e-10);
  }
  EXPECT_LT(iqn.updates, constant.updates);
  EXPECT_LT(aitken.updates, constant.updates);
}

}  // namespace
}  // namespace cosim::coupling::test
