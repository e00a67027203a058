// Interface quasi-Newton, inverse Jacobian by least squares (IQN-ILS, Degroote et al.
// 2009, as in preCICE). From the iterates of this window it fits how the output H moves
// with the residual r = H(x) - x,
//   V = [r_k - r_{k-1}, ..., r_k - r_0],  W = [H_k - H_{k-1}, ..., H_k - H_0],
//   alpha = argmin |V alpha + r_k|,       x_{k+1} = H_k + W alpha,
// which is a Newton step on every direction V spans: a linear problem in n unknowns is
// solved exactly by x_{n+1}, whatever its spectrum.
//
// Nothing is reused from earlier windows (new_window forgets everything). Reuse would save
// iterations, but then a run restarted from a checkpoint would take different iterates
// than the uninterrupted one; without it a restart is exact.
#include <vector>

#include "coupler/coupling/acceleration.hpp"
#include "coupler/coupling/least_squares.hpp"

namespace cosim::coupling {
namespace {

// Relative to the largest column of V; columns below it carry round-off, not information.
constexpr double filter_eps = 1e-10;

class IqnIls final : public Accelerator {
 public:
  explicit IqnIls(double w) : w_(w) {}

  void new_window() override {
    residuals_.clear();
    outputs_.clear();
  }

  Eigen::VectorXd next(const Eigen::VectorXd& x, const Eigen::VectorXd& hx) override {
    const Eigen::VectorXd r = hx - x;
    const Eigen::Index n = static_cast<Eigen::Index>(residuals_.size());
    Eigen::MatrixXd v(x.size(), n);
    Eigen::MatrixXd w(x.size(), n);
    for (Eigen::Index j = 0; j < n; ++j) {
      const auto i = static_cast<std::size_t>(n - 1 - j);  // most recent first
      v.col(j) = r - residuals_[i];
      w.col(j) = hx - outputs_[i];
    }
    residuals_.push_back(r);
    outputs_.push_back(hx);

    const LeastSquares fit = filtered_least_squares(v, -r, filter_eps);
    // With no usable column (first iteration, or only repeats of the same residual) there
    // is no slope to go on: relax, because a bare H(x) diverges on added-mass problems.
    if (fit.rank == 0) return x + w_ * r;
    return hx + w * fit.alpha;
  }

 private:
  double w_;
  std::vector<Eigen::VectorXd> residuals_;  // r_0 .. r_{k-1} of this window
  std::vector<Eigen::VectorXd> outputs_;    // H(x_0) .. H(x_{k-1})
};

}  // namespace

std::unique_ptr<Accelerator> make_iqn_ils(double w) { return std::make_unique<IqnIls>(w); }

}  // namespace cosim::coupling
