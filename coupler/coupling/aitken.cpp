// Aitken's dynamic relaxation (Irons & Tuck 1969, in the form of Küttler & Wall 2008):
// the factor is a secant estimate along the last step,
//   w_k = -w_{k-1} r_{k-1}^T (r_k - r_{k-1}) / |r_k - r_{k-1}|^2,
// which for a scalar linear problem is the exact inverse slope, so it then converges in
// two updates.
#include <cmath>
#include <optional>

#include "coupler/coupling/acceleration.hpp"

namespace cosim::coupling {
namespace {

class Aitken final : public Accelerator {
 public:
  explicit Aitken(double w) : first_(w), w_(w) {}

  void new_window() override {
    previous_.reset();
    w_ = first_;
  }

  Eigen::VectorXd next(const Eigen::VectorXd& x, const Eigen::VectorXd& hx) override {
    Eigen::VectorXd r = hx - x;
    if (previous_) {
      const Eigen::VectorXd dr = r - *previous_;
      const double w = -w_ * previous_->dot(dr) / dr.squaredNorm();
      // An unchanged residual (0/0) or an underflowing one (x/0) says nothing about the
      // slope: keep the last factor instead of poisoning every later iterate with NaN.
      if (std::isfinite(w)) w_ = w;
    }
    Eigen::VectorXd out = x + w_ * r;
    previous_ = std::move(r);
    return out;
  }

 private:
  double first_;
  double w_;
  std::optional<Eigen::VectorXd> previous_;  // r_{k-1}; empty at the start of a window
};

}  // namespace

std::unique_ptr<Accelerator> make_aitken(double w) { return std::make_unique<Aitken>(w); }

}  // namespace cosim::coupling
