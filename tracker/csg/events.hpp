#pragma once

#include <limits>

#include <Eigen/Core>

#include "tracker/csg/object.hpp"
#include "tracker/csg/state.hpp"

namespace cosim::tracker::csg {

// The next change of a particle's logical state on its ballistic path r(t) = x + v t.
// Every event flips one primitive's bit (enter or leave). When that flip changes whether the
// state is inside the object, the event is also a boundary: the particle is on the object's
// surface. A wall's boundary is not crossed: the caller reflects or absorbs the particle and
// the state stays. A permeable object's boundary is crossed and counted.
struct Event {
  double dt = std::numeric_limits<double>::infinity();  // from now, >= 0; infinity: none
  int primitive = -1;
  bool enters = false;  // into the primitive, else out of it
  bool boundary = false;
  bool into_object = false;                          // boundary: from outside the object to inside
  bool permeable = false;                            // boundary: of a permeable object
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // boundary: the object's outward unit normal there

  bool happens() const { return dt < std::numeric_limits<double>::infinity(); }
  bool reflects() const { return boundary && !permeable; }
};

// The earliest event over the object's primitives, each scheduled by the rule of Bannerman,
// Strobl and Poeschel: a primitive the state says the particle is outside of can only be
// entered, at the earliest dt >= 0 where f <= 0 and f' < 0; one it is inside of can only be
// left, where f >= 0 and f' > 0. A particle found slightly on the wrong side, moving the
// crossing way, gets dt = 0; never a negative time. Ties go to the lowest index; the other
// follows at dt = 0 from the new position.
Event next_event(const Tree& tree, bool permeable, State state, const Eigen::Vector3d& x, const Eigen::Vector3d& v);
inline Event next_event(const Object& object, State state, const Eigen::Vector3d& x, const Eigen::Vector3d& v) {
  return next_event(object.tree(), object.permeable(), state, x, v);
}

// The state after the event (the caller has moved the particle to x + v dt): the
// primitive's bit flips, except at a wall's boundary, where the state stays and the caller
// changes the velocity (or removes the particle).
State apply(State state, const Event& event);

// A rigid move of the object from its current pose to `new_pose`, seen by a particle at x
// that does not move meanwhile: in the object frame it moves from its old to its new
// object-frame position, on a straight line (exact for translations, first order in the
// angle for rotations). Its bits follow that relative path by the same events as tracking,
// so the state stays valid however close the particle is to the surface. Call it for every
// particle the move may sweep, before Object::set_pose(new_pose). A wall passing over the
// particle also flips its bits: the returned state is then inside the object, and the caller
// must push the particle out or remove it.
State sweep(const Object& object, State state, const Eigen::Vector3d& x, const Eigen::Isometry3d& new_pose);

// The same for a tree whose primitives are at the old pose, the particle moving by w
// relative to them (w = old_pose * new_pose^-1 * x - x). Also tells whether it ended inside
// the object (a wall overran it), with where it last entered: at x + at * w, through the
// surface with outward `normal`, `outside` being its state just before.
struct Swept {
  State state;
  bool overrun = false;
  double at = 0.0;
  State outside = 0;
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
};
Swept sweep(const Tree& tree, State state, const Eigen::Vector3d& x, const Eigen::Vector3d& w);

}  // namespace cosim::tracker::csg
