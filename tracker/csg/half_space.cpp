#include "tracker/csg/primitive.hpp"

namespace cosim::tracker::csg::detail {

double half_space_indicator(const Eigen::Vector3d& p) { return p.z(); }

Eigen::Vector3d half_space_gradient(const Eigen::Vector3d&) { return Eigen::Vector3d::UnitZ(); }

// f(t) = p_z + u_z t is linear: one root, entering when u_z < 0 (the facet rule of
// Bannerman et al.), leaving when u_z > 0; a parallel line is inside throughout or never.
Chord half_space_chord(const Eigen::Vector3d& p, const Eigen::Vector3d& u) {
  if (u.z() == 0.0) return p.z() < 0.0 ? Chord::whole() : Chord::empty();
  const double root = -p.z() / u.z();
  if (u.z() < 0.0) return {root, Chord::inf, Chord::inf};
  return {-Chord::inf, root, -Chord::inf};
}

}  // namespace cosim::tracker::csg::detail
