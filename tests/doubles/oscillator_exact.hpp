// The exact motion of the partitioned oscillator (README.md): modal superposition of the
// undamped two-mass system M e'' = -K e about its equilibrium.
#pragma once

#include <array>
#include <cmath>

#include <Eigen/Dense>

namespace cosim::doubles {

struct Oscillator {
  double m1 = 1, m2 = 1, k = 40, k2 = 40, rest = 1, anchor = 1;
  double x1 = 0.1, v1 = 0, x2 = 1, v2 = 0;  // initial state

  // x1(t), x2(t)
  std::array<double, 2> at(double t) const {
    const Eigen::Vector2d eq(anchor - rest, anchor);
    Eigen::Matrix2d M, K;
    M << m1, 0, 0, m2;
    K << k, -k, -k, k + k2;
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> modes(K, M);
    const Eigen::Matrix2d& phi = modes.eigenvectors();  // M-orthonormal
    const Eigen::Vector2d a = phi.transpose() * M * (Eigen::Vector2d(x1, x2) - eq);
    const Eigen::Vector2d b = phi.transpose() * M * Eigen::Vector2d(v1, v2);
    Eigen::Vector2d e = Eigen::Vector2d::Zero();
    for (int i = 0; i < 2; ++i) {
      const double w = std::sqrt(modes.eigenvalues()(i));
      e += phi.col(i) * (a(i) * std::cos(w * t) + b(i) / w * std::sin(w * t));
    }
    return {eq(0) + e(0), eq(1) + e(1)};
  }
};

}  // namespace cosim::doubles
