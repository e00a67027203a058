// Least squares with a rank filter, the core of IQN-ILS: the columns of V are differences
// of residuals, and late in a window they become nearly parallel, so a plain QR would
// divide by almost zero and blow the step up.
#pragma once

#include <Eigen/Dense>

namespace cosim::coupling {

struct LeastSquares {
  Eigen::VectorXd alpha;  // one coefficient per column of V
  Eigen::Index rank = 0;  // how many columns survived the filter
};

// Returns alpha minimising |V alpha - b| over the columns of V that survive the filter
// (the others get alpha = 0). Columns are taken in order, so earlier ones win: column j is
// dropped when the part of it orthogonal to the columns already kept, which is |R_jj| of
// the QR of the kept columns, is at most eps times the largest column norm of V. Measuring
// against the largest column rather than R_00 keeps the test meaningful when the first
// column is itself zero.
LeastSquares filtered_least_squares(const Eigen::MatrixXd& v, const Eigen::VectorXd& b, double eps);

}  // namespace cosim::coupling
