// The QR filter: dependent columns must be dropped, not divided by.
#include <gtest/gtest.h>

#include "coupler/coupling/least_squares.hpp"
#include "tests/coupling/problems.hpp"

namespace cosim::coupling::test {
namespace {

constexpr double eps = 1e-10;

bool finite(const Eigen::VectorXd& v) { return v.allFinite(); }

TEST(FilteredLeastSquares, DropsAMultipleOfAnEarlierColumn) {
  const Eigen::VectorXd a = random_vector(6, 1);
  const Eigen::VectorXd c = random_vector(6, 2);
  Eigen::MatrixXd v(6, 3);
  v << a, 2.0 * a, c;
  const Eigen::VectorXd b = 0.5 * a - 3.0 * c;
  const LeastSquares fit = filtered_least_squares(v, b, eps);
  EXPECT_EQ(fit.rank, 2);
  EXPECT_EQ(fit.alpha(1), 0.0);
  EXPECT_NEAR(fit.alpha(0), 0.5, 1e-12);
  EXPECT_NEAR(fit.alpha(2), -3.0, 1e-12);
}

TEST(FilteredLeastSquares, ZeroColumnsGiveRankZero) {
  const LeastSquares fit = filtered_least_squares(Eigen::MatrixXd::Zero(4, 2), random_vector(4, 3), eps);
  EXPECT_EQ(fit.rank, 0);
  EXPECT_TRUE(fit.alpha.isZero(0.0));
}

TEST(FilteredLeastSquares, MoreColumnsThanRowsKeepsAtMostTheRowCount) {
  Eigen::MatrixXd v(3, 5);
  for (Eigen::Index j = 0; j < 5; ++j) v.col(j) = random_vector(3, 10 + static_cast<unsigned>(j));
  const Eigen::VectorXd b = random_vector(3, 20);
  const LeastSquares fit = filtered_least_squares(v, b, eps);
  EXPECT_EQ(fit.rank, 3);
  EXPECT_LT((v * fit.alpha - b).norm(), 1e-12);
}

// Handing IQN-ILS the same (x, H(x)) twice makes V hold a zero column, then two equal
// ones. The filter has to drop them and leave the step the clean history would give.
// Guards against: a repeated (x, H(x)) making IQN-ILS divide by a zero column (NaN).
TEST(IqnIlsFilter, RepeatedResidualGivesNoNaN) {
  const Problem problem = linear(Eigen::VectorXd::LinSpaced(5, -3.0, -1.0), 5);
  const Eigen::VectorXd x0 = Eigen::VectorXd::Zero(5);
  const auto clean = make_iqn_ils(0.1);
  const Eigen::VectorXd x1 = clean->next(x0, problem.h(x0));
  const Eigen::VectorXd x2 = clean->next(x1, problem.h(x1));

  const auto repeated = make_iqn_ils(0.1);
  repeated->next(x0, problem.h(x0));
  const Eigen::VectorXd again = repeated->next(x0, problem.h(x0));
  EXPECT_TRUE(finite(again));
  EXPECT_TRUE(again.isApprox(x1, 1e-14));
  const Eigen::VectorXd x2_repeated = repeated->next(x1, problem.h(x1));
  EXPECT_TRUE(finite(x2_repeated));
  EXPECT_TRUE(x2_repeated.isApprox(x2, 1e-12));
}

// A participant that answers twice per iteration must not cost IQN-ILS its convergence.
// Guards against: duplicate evaluations costing IQN-ILS its convergence.
TEST(IqnIlsFilter, EveryEvaluationSubmittedTwiceStillConverges) {
  const Eigen::Index n = 6;
  const Problem problem = linear(Eigen::VectorXd::LinSpaced(n, -3.0, -1.0), 6);
  const auto iqn = make_iqn_ils(0.1);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  int updates = 0;
  for (; updates <= n + 1; ++updates) {
    const Eigen::VectorXd hx = problem.h(x);
    if ((hx - x).norm() <= residual_tolerance) break;
    iqn->next(x, hx);
    x = iqn->next(x, hx);
    ASSERT_TRUE(finite(x));
  }
  EXPECT_LE(updates, n + 1);
  EXPECT_LT((x - problem.solution).norm(), 1e-10);
}

}  // namespace
}  // namespace cosim::coupling::test
