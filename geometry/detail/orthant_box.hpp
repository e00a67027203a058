#pragma once

#include <Eigen/Core>

namespace cosim::geometry::detail {

// Closest point on the box [-h, h]^N for a query folded into the positive orthant (a >= 0).
// Box and cylinder share it: a cylinder is the 2D box (radius, half height) in the
// coordinates (distance from the axis, |z|). Points on a face give exactly zero: q_i = 0.
// Where faces tie (edges and corners, and the medial axis inside) the normal bisects them,
// as a mesh's pseudo-normal does.
template <int N>
struct OrthantBoxPoint {
  using Vec = Eigen::Matrix<double, N, 1>;
  double distance;
  Vec point;
  Vec normal;
};

template <int N>
double orthant_box_distance(const Eigen::Matrix<double, N, 1>& a, const Eigen::Matrix<double, N, 1>& h) {
  const Eigen::Matrix<double, N, 1> q = a - h;
  const double q_max = q.maxCoeff();
  return q_max <= 0.0 ? q_max : q.cwiseMax(0.0).norm();
}

template <int N>
OrthantBoxPoint<N> orthant_box_closest(const Eigen::Matrix<double, N, 1>& a, const Eigen::Matrix<double, N, 1>& h) {
  using Vec = Eigen::Matrix<double, N, 1>;
  const Vec q = a - h;
  Eigen::Index i = 0;
  const double q_max = q.maxCoeff(&i);
  if (q_max <= 0.0) {  // inside: the nearest face is the one with the largest q
    Vec point = a;
    point[i] = h[i];
    const Vec ties = (q.array() == q_max).template cast<double>();
    return {q_max, point, ties.normalized()};
  }
  const Vec point = a.cwiseMin(h);
  const Vec diff = a - point;
  const double d = diff.norm();  // > 0 because some q_i > 0
  return {d, point, diff / d};
}

}  // namespace cosim::geometry::detail
