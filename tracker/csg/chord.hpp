#pragma once

#include <limits>

namespace cosim::tracker::csg {

// Where a line r(t) = r0 + v t is inside a convex primitive: the open interval (in, out),
// possibly unbounded. Every primitive is convex, so one interval says everything the event
// rules need. `mid` is the time of deepest approach (in <= mid <= out): before it the
// particle moves inward (f' < 0), after it outward. A line that misses, or only touches the
// surface (a double root), has an empty chord {0, 0, 0}: touching is not entering.
struct Chord {
  double in;
  double out;
  double mid;

  static constexpr double inf = std::numeric_limits<double>::infinity();
  static constexpr Chord empty() { return {0.0, 0.0, 0.0}; }
  // The whole line is inside and never moves in or out (f' = 0), so it has no event.
  static constexpr Chord whole() { return {-inf, inf, 0.0}; }

  bool is_empty() const { return !(in < out); }
};

}  // namespace cosim::tracker::csg
