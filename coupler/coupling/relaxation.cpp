// The two static schemes: neither keeps state, so new_window has nothing to forget.
#include "coupler/coupling/acceleration.hpp"

namespace cosim::coupling {
namespace {

class FixedPoint final : public Accelerator {
 public:
  void new_window() override {}
  // Returned as is rather than as x + 1 * (hx - x), which would not round back to hx.
  Eigen::VectorXd next(const Eigen::VectorXd&, const Eigen::VectorXd& hx) override { return hx; }
};

class Constant final : public Accelerator {
 public:
  explicit Constant(double w) : w_(w) {}
  void new_window() override {}
  Eigen::VectorXd next(const Eigen::VectorXd& x, const Eigen::VectorXd& hx) override { return x + w_ * (hx - x); }

 private:
  double w_;
};

}  // namespace

std::unique_ptr<Accelerator> make_fixed_point() { return std::make_unique<FixedPoint>(); }

std::unique_ptr<Accelerator> make_constant(double w) { return std::make_unique<Constant>(w); }

}  // namespace cosim::coupling
