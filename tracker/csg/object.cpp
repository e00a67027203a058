#include "tracker/csg/object.hpp"

#include <stdexcept>
#include <string>

namespace cosim::tracker::csg {

Object::Object(const Expression& expression, bool permeable, const Eigen::Isometry3d& pose)
    : tree_(expression), permeable_(permeable), pose_(Eigen::Isometry3d::Identity()) {
  if (primitive_count() > max_primitives)
    throw std::invalid_argument("csg object: " + std::to_string(primitive_count()) + " primitives, at most " +
                                std::to_string(max_primitives) + " fit in a logical state");
  set_pose(pose);
}

void Object::set_pose(const Eigen::Isometry3d& pose) {
  pose_ = pose;
  for (Primitive& p : tree_.primitives()) p.place(pose);
}

State Object::classify(const Eigen::Vector3d& x) const { return tree_.classify(x); }

}  // namespace cosim::tracker::csg
