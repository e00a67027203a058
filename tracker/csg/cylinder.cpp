#include "tracker/csg/detail/unit_ball_chord.hpp"
#include "tracker/csg/primitive.hpp"

namespace cosim::tracker::csg::detail {

double cylinder_indicator(const Eigen::Vector3d& p) { return p.head<2>().squaredNorm() - 1.0; }

Eigen::Vector3d cylinder_gradient(const Eigen::Vector3d& p) { return {p.x(), p.y(), 0.0}; }

// The infinite cylinder is the unit disc swept along z: its chord is the disc's chord of the
// line projected on the xy plane (same time parameter).
Chord cylinder_chord(const Eigen::Vector3d& p, const Eigen::Vector3d& u) {
  return unit_ball_chord(Eigen::Vector2d(p.head<2>()), Eigen::Vector2d(u.head<2>()));
}

}  // namespace cosim::tracker::csg::detail
