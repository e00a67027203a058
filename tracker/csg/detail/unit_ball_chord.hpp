#pragma once

#include <algorithm>
#include <cmath>

#include "tracker/csg/chord.hpp"

namespace cosim::tracker::csg::detail {

// Chord of the line p + t u through the open unit ball |x| < 1, in 2D (the cylinder's
// cross-section) or 3D. The discriminant is taken from the distance of the line to the
// centre, 1 - |p_perp|^2, not from b^2 - a c, which cancels catastrophically for a particle
// far from a small ball. The roots use q = -(b + sign(b) sqrt(disc)) so that neither
// subtracts nearly equal numbers: t = q / a and t = c / q.
template <class Vec>
Chord unit_ball_chord(const Vec& p, const Vec& u) {
  const double a = u.squaredNorm();
  const double c = p.squaredNorm() - 1.0;
  if (!(a > 0.0)) return c < 0.0 ? Chord::whole() : Chord::empty();
  const double b = p.dot(u);
  const double closest = -b / a;
  const double miss = 1.0 - (p + closest * u).squaredNorm();
  if (!(miss > 0.0)) return Chord::empty();
  const double q = -(b + std::copysign(std::sqrt(a * miss), b));
  const double t1 = q / a;
  const double t2 = c / q;
  const double in = std::min(t1, t2);
  const double out = std::max(t1, t2);
  if (!(in < out)) return Chord::empty();
  return {in, out, std::clamp(closest, in, out)};
}

}  // namespace cosim::tracker::csg::detail
