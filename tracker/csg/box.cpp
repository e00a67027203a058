#include <algorithm>
#include <cmath>

#include "tracker/csg/primitive.hpp"

namespace cosim::tracker::csg::detail {

double box_indicator(const Eigen::Vector3d& p) { return p.cwiseAbs().maxCoeff() - 1.0; }

// The face nearest in the max norm; on an edge or corner, the first of the tied faces.
Eigen::Vector3d box_gradient(const Eigen::Vector3d& p) {
  Eigen::Index k = 0;
  p.cwiseAbs().maxCoeff(&k);
  Eigen::Vector3d g = Eigen::Vector3d::Zero();
  g[k] = p[k] < 0.0 ? -1.0 : 1.0;
  return g;
}

// A native box (one state bit instead of six half-spaces): the intersection of the three
// slabs' open intervals.
Chord box_chord(const Eigen::Vector3d& p, const Eigen::Vector3d& u) {
  double in = -Chord::inf;
  double out = Chord::inf;
  for (int i = 0; i < 3; ++i) {
    if (u[i] == 0.0) {
      if (!(std::abs(p[i]) < 1.0)) return Chord::empty();
      continue;
    }
    const double t1 = (-1.0 - p[i]) / u[i];
    const double t2 = (1.0 - p[i]) / u[i];
    in = std::max(in, std::min(t1, t2));
    out = std::min(out, std::max(t1, t2));
  }
  if (in == -Chord::inf) return Chord::whole();
  if (!(in < out)) return Chord::empty();
  return {in, out, 0.5 * (in + out)};
}

}  // namespace cosim::tracker::csg::detail
