#include "tracker/tracers/velocity_field.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace cosim::tracker::tracers {
namespace {

// The cell of the axis holding x and the weight of its upper point, clamped to the ends.
std::pair<std::size_t, double> locate(const std::vector<double>& axis, double x) {
  if (axis.size() == 1 || x <= axis.front()) return {0, 0.0};
  if (x >= axis.back()) return {axis.size() - 2, 1.0};
  const auto upper = std::upper_bound(axis.begin(), axis.end(), x);
  const auto i = static_cast<std::size_t>(upper - axis.begin()) - 1;
  return {i, (x - axis[i]) / (axis[i + 1] - axis[i])};
}

}  // namespace

VelocityField::VelocityField(std::array<std::vector<double>, 3> axes, std::vector<double> values)
    : axes_(std::move(axes)), values_(std::move(values)) {
  std::size_t points = 3;
  for (int k = 0; k < 3; ++k) {
    const std::vector<double>& a = axes_[static_cast<std::size_t>(k)];
    if (a.empty()) throw std::invalid_argument("velocity field: axis " + std::to_string(k) + " has no points");
    for (std::size_t i = 1; i < a.size(); ++i)
      if (!(a[i] > a[i - 1]))
        throw std::invalid_argument("velocity field: axis " + std::to_string(k) + " is not increasing at point " +
                                    std::to_string(i));
    points *= a.size();
  }
  if (values_.size() != points)
    throw std::invalid_argument("velocity field: " + std::to_string(values_.size()) + " values for " +
                                std::to_string(points / 3) + " points (3 components each)");
}

Vec3 VelocityField::at(std::size_t i, std::size_t j, std::size_t k) const {
  const std::size_t p = 3 * (i + axes_[0].size() * (j + axes_[1].size() * k));
  return {values_[p], values_[p + 1], values_[p + 2]};
}

Vec3 VelocityField::operator()(const Vec3& x) const {
  const auto [i, wx] = locate(axes_[0], x.x());
  const auto [j, wy] = locate(axes_[1], x.y());
  const auto [k, wz] = locate(axes_[2], x.z());
  // A single point on an axis has no upper neighbour: its weight is 0 there.
  const std::size_t di = axes_[0].size() > 1, dj = axes_[1].size() > 1, dk = axes_[2].size() > 1;
  Vec3 u = Vec3::Zero();
  for (int c = 0; c < 8; ++c) {
    const bool up_x = c & 1, up_y = c & 2, up_z = c & 4;
    const double w = (up_x ? wx : 1 - wx) * (up_y ? wy : 1 - wy) * (up_z ? wz : 1 - wz);
    if (w == 0.0) continue;
    u += w * at(i + (up_x ? di : 0), j + (up_y ? dj : 0), k + (up_z ? dk : 0));
  }
  return u;
}

std::vector<double> uniform_axis(double lo, double hi, int n) {
  std::vector<double> axis(static_cast<std::size_t>(n) + 1);
  for (int i = 0; i <= n; ++i) axis[static_cast<std::size_t>(i)] = lo + (hi - lo) * i / n;
  return axis;
}

}  // namespace cosim::tracker::tracers
