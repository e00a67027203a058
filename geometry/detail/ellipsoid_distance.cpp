#include "geometry/detail/ellipsoid_distance.hpp"

#include <cmath>
#include <limits>

namespace cosim::geometry::detail {
namespace {

// Enough halvings to go from any bracket to adjacent doubles; the loop stops much earlier.
constexpr int max_iterations = std::numeric_limits<double>::digits - std::numeric_limits<double>::min_exponent;

// Root of Eberly's secular equation F(s) = sum_i (r_i z_i / (s + r_i))^2 - 1 = 0
// (r_last = 1) on his bracket [z_last - 1, |r .* z| - 1] (upper end 0 for inside points,
// g < 0). Two changes to his plain bisection:
// - it is solved for u = s + 1: for inside points close to the plane of the smallest axis
//   the root sits next to the pole s = -1, where s would keep only the absolute precision
//   of 1 and x_last = y_last / (s + 1) would lose most of its digits;
// - the bracket is shrunk by Newton steps whenever they land inside it, by halving
//   otherwise. F is convex and decreasing, so Newton from the left end climbs monotonically
//   to the root: a handful of iterations instead of ~60 halvings, same robustness.
// Returns u.
template <int N>
double secular_root(const Eigen::Matrix<double, N, 1>& r, const Eigen::Matrix<double, N, 1>& z, double g) {
  const Eigen::Array<double, N, 1> n = r.cwiseProduct(z).array();
  const Eigen::Array<double, N, 1> offset = r.array() - 1.0;   // s + r_i = u + offset_i
  double lo = z[N - 1];                                        // F(lo) >= 0
  double hi = g < 0.0 ? 1.0 : r.cwiseProduct(z).stableNorm();  // F(hi) <= 0
  double u = lo;
  for (int i = 0; i < max_iterations; ++i) {
    const Eigen::Array<double, N, 1> ratio = n / (u + offset);
    const double f = ratio.square().sum() - 1.0;
    if (f > 0.0)
      lo = u;
    else if (f < 0.0)
      hi = u;
    else
      return u;
    const double slope = -2.0 * (ratio.square() / (u + offset)).sum();
    const double newton = u - f / slope;
    if (newton > lo && newton < hi && newton != u) {
      u = newton;
      continue;
    }
    const double mid = 0.5 * (lo + hi);
    if (mid == lo || mid == hi) break;
    // Newton stalled on a rounding plateau next to the root: it is found.
    if (newton == u) break;
    u = mid;
  }
  return u;
}

// 2D: ellipse with e0 >= e1 > 0, y in the first quadrant.
Eigen::Vector2d closest_on_ellipse_quadrant(const Eigen::Vector2d& e, const Eigen::Vector2d& y) {
  if (y[1] > 0.0) {
    if (y[0] > 0.0) {
      const Eigen::Vector2d z = y.cwiseQuotient(e);
      const double g = z.squaredNorm() - 1.0;
      if (g == 0.0) return y;
      const Eigen::Vector2d r(std::pow(e[0] / e[1], 2), 1.0);
      const double u = secular_root<2>(r, z, g);
      return {r[0] * y[0] / (u + (r[0] - 1.0)), y[1] / u};
    }
    return {0.0, e[1]};
  }
  // On the major axis: inside the evolute the closest point leaves the axis.
  const double numer = e[0] * y[0];
  const double denom = e[0] * e[0] - e[1] * e[1];
  if (numer < denom) {
    const double xde = numer / denom;
    return {e[0] * xde, e[1] * std::sqrt(1.0 - xde * xde)};
  }
  return {e[0], 0.0};
}

}  // namespace

Eigen::Vector3d closest_on_ellipsoid_octant(const Eigen::Vector3d& e, const Eigen::Vector3d& y) {
  if (y[2] > 0.0) {
    if (y[1] > 0.0 && y[0] > 0.0) {
      const Eigen::Vector3d z = y.cwiseQuotient(e);
      const double g = z.squaredNorm() - 1.0;
      if (g == 0.0) return y;
      const Eigen::Vector3d r(std::pow(e[0] / e[2], 2), std::pow(e[1] / e[2], 2), 1.0);
      const double u = secular_root<3>(r, z, g);
      return r.cwiseProduct(y).cwiseQuotient((r.array() - 1.0 + u).matrix());
    }
    if (y[1] > 0.0) {  // y0 == 0: the problem lives in the (1, 2) plane
      const Eigen::Vector2d x = closest_on_ellipse_quadrant({e[1], e[2]}, {y[1], y[2]});
      return {0.0, x[0], x[1]};
    }
    if (y[0] > 0.0) {  // y1 == 0
      const Eigen::Vector2d x = closest_on_ellipse_quadrant({e[0], e[2]}, {y[0], y[2]});
      return {x[0], 0.0, x[1]};
    }
    return {0.0, 0.0, e[2]};  // on the minor axis
  }
  // y2 == 0: an inside point near the (0, 1) plane may still be closest to a point off it.
  const Eigen::Vector2d numer(e[0] * y[0], e[1] * y[1]);
  const Eigen::Vector2d denom(e[0] * e[0] - e[2] * e[2], e[1] * e[1] - e[2] * e[2]);
  if (numer[0] < denom[0] && numer[1] < denom[1]) {
    const Eigen::Vector2d xde = numer.cwiseQuotient(denom);
    const double discr = 1.0 - xde.squaredNorm();
    if (discr > 0.0) return {e[0] * xde[0], e[1] * xde[1], e[2] * std::sqrt(discr)};
  }
  const Eigen::Vector2d x = closest_on_ellipse_quadrant({e[0], e[1]}, {y[0], y[1]});
  return {x[0], x[1], 0.0};
}

}  // namespace cosim::geometry::detail
