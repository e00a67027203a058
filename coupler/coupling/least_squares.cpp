#include "coupler/coupling/least_squares.hpp"

#include <vector>

namespace cosim::coupling {

// Gram-Schmidt builds the QR one column at a time, which is what lets a column be judged
// against exactly the columns kept before it. Orthogonalising twice ("twice is enough",
// Giraud et al. 2005) keeps Q as orthogonal as Householder would.
LeastSquares filtered_least_squares(const Eigen::MatrixXd& v, const Eigen::VectorXd& b, double eps) {
  const Eigen::Index n = v.cols();
  if (n == 0) return {Eigen::VectorXd(0), 0};
  const double threshold = eps * v.colwise().norm().maxCoeff();
  Eigen::MatrixXd q(v.rows(), n);
  Eigen::MatrixXd r = Eigen::MatrixXd::Zero(n, n);
  std::vector<Eigen::Index> kept;
  for (Eigen::Index j = 0; j < n; ++j) {
    const Eigen::Index p = static_cast<Eigen::Index>(kept.size());
    Eigen::VectorXd u = v.col(j);
    Eigen::VectorXd coefficients = Eigen::VectorXd::Zero(p);
    for (int pass = 0; pass < 2; ++pass) {
      const Eigen::VectorXd c = q.leftCols(p).transpose() * u;
      u -= q.leftCols(p) * c;
      coefficients += c;
    }
    const double norm = u.norm();
    if (norm <= threshold) continue;
    q.col(p) = u / norm;
    r.col(p).head(p) = coefficients;
    r(p, p) = norm;
    kept.push_back(j);
  }
  const Eigen::Index p = static_cast<Eigen::Index>(kept.size());
  const Eigen::VectorXd y = r.topLeftCorner(p, p).triangularView<Eigen::Upper>().solve(q.leftCols(p).transpose() * b);
  LeastSquares fit{Eigen::VectorXd::Zero(n), p};
  for (Eigen::Index i = 0; i < p; ++i) fit.alpha(kept[static_cast<std::size_t>(i)]) = y(i);
  return fit;
}

}  // namespace cosim::coupling
