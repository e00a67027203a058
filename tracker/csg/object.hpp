#pragma once

#include <Eigen/Geometry>

#include "tracker/csg/expression.hpp"
#include "tracker/csg/state.hpp"
#include "tracker/csg/tree.hpp"

namespace cosim::tracker::csg {

// A CSG obstacle or zone: the normal-form tree of its expression (given in the object frame)
// placed in the world by a rigid pose. A wall reflects or absorbs particles at its surface; a
// permeable object lets them through and only reports that they entered or left it.
class Object {
 public:
  explicit Object(const Expression& expression, bool permeable = false,
                  const Eigen::Isometry3d& pose = Eigen::Isometry3d::Identity());

  bool permeable() const { return permeable_; }
  const Tree& tree() const { return tree_; }
  int primitive_count() const { return static_cast<int>(tree_.primitives().size()); }
  const Eigen::Isometry3d& pose() const { return pose_; }
  // Moves the object rigidly; see sweep() in events.hpp for the particles it passes over.
  void set_pose(const Eigen::Isometry3d& pose);

  // Inside the object according to a logical state: the only test tracking uses.
  bool inside(State state) const { return tree_.evaluate(state); }
  // The state of a particle at x by direct evaluation of every primitive. Only valid away
  // from all surfaces (round-off decides the bits there): for initialising particles and for
  // re-labelling them far from the object, never during tracking.
  State classify(const Eigen::Vector3d& x) const;

 private:
  Tree tree_;
  bool permeable_;
  Eigen::Isometry3d pose_;
};

}  // namespace cosim::tracker::csg
