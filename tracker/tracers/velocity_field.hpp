#pragma once
// A velocity field given at the points of a rectilinear grid (the fluid's cell centres, or
// any sampled field), interpolated trilinearly. Outside the grid's points the nearest
// boundary values hold (constant extrapolation), so tracers near a wall see the last
// sample rather than garbage.

#include "tracker/mesh/mesh.hpp"

#include <array>
#include <vector>

namespace cosim::tracker::tracers {

class VelocityField {
 public:
  // `axes[k]` the strictly increasing coordinates along axis k (at least one each);
  // `values` three components per point, x fastest, then y, then z. Throws
  // std::invalid_argument on sizes or order.
  VelocityField(std::array<std::vector<double>, 3> axes, std::vector<double> values);

  Vec3 operator()(const Vec3& x) const;

  // A field sampled from a function at the points of the grid (tests, analytic flows).
  template <typename F>
  static VelocityField sampled(std::array<std::vector<double>, 3> axes, const F& u) {
    std::vector<double> values;
    for (const double z : axes[2])
      for (const double y : axes[1])
        for (const double x : axes[0]) {
          const Vec3 v = u(Vec3(x, y, z));
          values.insert(values.end(), {v.x(), v.y(), v.z()});
        }
    return VelocityField(std::move(axes), std::move(values));
  }

 private:
  Vec3 at(std::size_t i, std::size_t j, std::size_t k) const;

  std::array<std::vector<double>, 3> axes_;
  std::vector<double> values_;
};

// n + 1 equally spaced coordinates from lo to hi.
std::vector<double> uniform_axis(double lo, double hi, int n);

}  // namespace cosim::tracker::tracers
