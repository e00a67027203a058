#include "fluid/program/confined_inflow.hpp"

#include <memory>
#include <stdexcept>

namespace cosim::fluid::program {
namespace {

// Sample points per cell and tangential axis: the fraction of a cell the wall cuts is
// within 1/kSamples of its area.
constexpr int kSamples = 16;

}  // namespace

fluid::grid::VelocityFunction confined_inflow(fluid::grid::VelocityFunction profile,
                                              const geometry::Container& container, const geometry::Pose& pose,
                                              int axis, fluid::grid::Side side,
                                              const std::vector<fluid::grid::Axis>& axes) {
  const int t1 = (axis + 1) % 3, t2 = (axis + 2) % 3;
  const fluid::grid::Axis a1 = axes[static_cast<std::size_t>(t1)], a2 = axes[static_cast<std::size_t>(t2)];
  const fluid::grid::Axis& normal = axes[static_cast<std::size_t>(axis)];
  auto fraction = std::make_shared<std::vector<double>>(static_cast<std::size_t>(a1.cells() * a2.cells()));
  Eigen::Vector3d x;
  x[axis] = side == fluid::grid::Side::lower ? normal.lo() : normal.hi();
  double open = 0;
  for (int j = 0; j < a2.cells(); ++j)
    for (int i = 0; i < a1.cells(); ++i) {
      int inside = 0;
      for (int sj = 0; sj < kSamples; ++sj)
        for (int si = 0; si < kSamples; ++si) {
          x[t1] = a1.face(i) + (si + 0.5) / kSamples * a1.width(i);
          x[t2] = a2.face(j) + (sj + 0.5) / kSamples * a2.width(j);
          inside += container.signed_distance(pose.to_body(x)) > 0 ? 1 : 0;  // contains() is the solid
        }
      const double f = static_cast<double>(inside) / (kSamples * kSamples);
      (*fraction)[static_cast<std::size_t>(j * a1.cells() + i)] = f;
      open += f;
    }
  if (open == 0) throw std::invalid_argument("no part of the face lies inside the container");
  return [=](const fluid::grid::Point& p, double t) {
    const double f = (*fraction)[static_cast<std::size_t>(a2.cell_at(p[static_cast<std::size_t>(t2)]) * a1.cells() +
                                                          a1.cell_at(p[static_cast<std::size_t>(t1)]))];
    const fluid::grid::Point u = profile(p, t);
    return fluid::grid::Point{f * u[0], f * u[1], f * u[2]};
  };
}

}  // namespace cosim::fluid::program
