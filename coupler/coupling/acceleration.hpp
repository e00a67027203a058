// Convergence acceleration for implicit coupling: the coupler iterates x = H(x) within a
// window, where x is the exchanged data (forces, or poses and forces stacked) and H is one
// pass through the participants. Each accelerator turns (x_k, H(x_k)) into x_{k+1}.
#pragma once

#include <memory>
#include <vector>

#include <Eigen/Dense>

#include "coupler/coupling/acceleration_kind.hpp"

namespace cosim::coupling {

class Accelerator {
 public:
  virtual ~Accelerator() = default;
  // Forget the iterates of the previous window.
  virtual void new_window() = 0;
  // x: the input used in this iteration; hx: what the participants returned for it.
  // Returns the input for the next iteration.
  virtual Eigen::VectorXd next(const Eigen::VectorXd& x, const Eigen::VectorXd& hx) = 0;
};

// x_{k+1} = H(x_k): plain fixed-point iteration.
std::unique_ptr<Accelerator> make_fixed_point();
// x_{k+1} = x_k + w r_k with r_k = H(x_k) - x_k.
std::unique_ptr<Accelerator> make_constant(double w);
// Aitken's dynamic under-relaxation; w is the first factor of every window.
std::unique_ptr<Accelerator> make_aitken(double w);
// Interface quasi-Newton with inverse Jacobian from a least-squares fit (IQN-ILS,
// Degroote et al. 2009); the first iteration of a window is relaxed by w. Columns that
// make the fit ill-conditioned are dropped (QR filter).
std::unique_ptr<Accelerator> make_iqn_ils(double w);

std::unique_ptr<Accelerator> make_accelerator(Acceleration kind, double w);

}  // namespace cosim::coupling
