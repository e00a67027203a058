// The impulses of a small contact group, solved at once instead of point by point.
// Gauss-Seidel passes a load through a light body a fraction m_light / m_heavy per sweep,
// so a heavy body on a light one needs thousands of sweeps (README.md); a direct solve of
// the group's problem needs none, whatever the mass ratio.
#pragma once

#include <cstdint>

#include <span>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "rigidbody/solver/contact_frame.hpp"

namespace cosim::rigidbody::solver {

class ContactBlock {
 public:
  // Rows: the first `axes` local axes of every frame (1: the normals; 3: normal and both
  // tangents), point by point. K = W + diag(compliance): W the rows' Delassus matrix
  // (velocity along row j per unit impulse along row i), `compliance` one per row.
  ContactBlock(std::span<const ContactFrame> frames, int axes, std::span<const Mobility> mobility,
               std::span<const double> compliance);

  // The mixed LCP of the rows: new impulses x, normal rows x >= 0, tangent rows free, with
  //   w = u + W (x - lambda) + compliance x - target >= 0 on normal rows, 0 where x > 0 and on
  // tangent rows; u the rows' velocities now, lambda their impulses now (replaced by x).
  // Friction is not bounded here: the caller caps it (a sticking group needs no cap).
  // Active set: the points that push are solved as equalities, the rest get zero
  // (Lawson-Hanson, see the .cpp).
  void solve(std::span<const double> u, std::span<const double> target, std::span<double> lambda);

 private:
  void factorize(const std::vector<int>& active);
  Eigen::VectorXd free_solution(const std::vector<int>& free, const Eigen::VectorXd& q);

  int axes_ = 1;
  Eigen::MatrixXd w_;  // W
  Eigen::VectorXd compliance_;
  std::vector<int> factorized_;  // the active set ldlt_ holds
  Eigen::LDLT<Eigen::MatrixXd> ldlt_;
};

}  // namespace cosim::rigidbody::solver
