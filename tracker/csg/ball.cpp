#include "tracker/csg/detail/unit_ball_chord.hpp"
#include "tracker/csg/primitive.hpp"

namespace cosim::tracker::csg::detail {

double ball_indicator(const Eigen::Vector3d& p) { return p.squaredNorm() - 1.0; }

Eigen::Vector3d ball_gradient(const Eigen::Vector3d& p) { return p; }

Chord ball_chord(const Eigen::Vector3d& p, const Eigen::Vector3d& u) { return unit_ball_chord(p, u); }

}  // namespace cosim::tracker::csg::detail
