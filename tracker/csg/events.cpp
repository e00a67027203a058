#include "tracker/csg/events.hpp"

#include <algorithm>

namespace cosim::tracker::csg {
namespace {

// Outside the primitive: the entering root, clamped to 0 when the particle is already
// slightly in and still moving inward (before the chord's midpoint). Past the midpoint it
// is on its way out and gets no event, which is what keeps a particle that just left from
// re-entering on round-off. An empty chord (a miss or a tangent line) is never entered.
double enter_time(const Chord& c) { return c.in < c.out && c.mid > 0.0 ? std::max(0.0, c.in) : Chord::inf; }

// Inside the primitive: the leaving root, clamped to 0 when it is already behind; an empty
// chord means the particle is outside, so it leaves at once. Since enter_time requires
// out > mid > 0, an enter at 0 is never followed by a leave at 0 and vice versa: zero-time
// events cannot cycle.
double leave_time(const Chord& c) { return std::max(0.0, c.out); }

}  // namespace

Event next_event(const Tree& tree, bool permeable, State state, const Eigen::Vector3d& x, const Eigen::Vector3d& v) {
  const auto& primitives = tree.primitives();
  Event event;
  for (int i = 0; i < static_cast<int>(primitives.size()); ++i) {
    const Chord chord = primitives[i].chord(x, v);
    const double dt = test(state, i) ? leave_time(chord) : enter_time(chord);
    if (dt < event.dt) {
      event.dt = dt;
      event.primitive = i;
    }
  }
  if (!event.happens()) return event;

  const int i = event.primitive;
  event.enters = !test(state, i);
  event.into_object = tree.evaluate(state ^ bit(i));
  event.boundary = event.into_object != tree.evaluate(state);
  event.permeable = permeable;
  if (event.boundary) {
    const Eigen::Vector3d n = primitives[i].normal(x + event.dt * v);
    event.normal = tree.complemented(i) ? Eigen::Vector3d(-n) : n;
  }
  return event;
}

State apply(State state, const Event& event) { return event.reflects() ? state : state ^ bit(event.primitive); }

State sweep(const Object& object, State state, const Eigen::Vector3d& x, const Eigen::Isometry3d& new_pose) {
  return sweep(object.tree(), state, x, object.pose() * (new_pose.inverse() * x) - x).state;
}

Swept sweep(const Tree& tree, State state, const Eigen::Vector3d& x, const Eigen::Vector3d& w) {
  Swept out{state};
  Eigen::Vector3d position = x;
  double done = 0.0;
  while (true) {
    const Event event = next_event(tree, false, out.state, position, w);
    if (!(event.dt <= 1.0 - done)) break;
    position += event.dt * w;
    done += event.dt;
    if (event.boundary && event.into_object) {
      out.at = done;
      out.outside = out.state;
      out.normal = event.normal;
    }
    out.state ^= bit(event.primitive);
  }
  out.overrun = tree.evaluate(out.state);
  return out;
}

}  // namespace cosim::tracker::csg
