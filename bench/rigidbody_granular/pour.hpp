// The poured-spheres scene both engines run: N equal spheres on a jittered lattice above
// the floor of an open box, falling and packing under gravity with frictional contacts.
#pragma once

#include <cstddef>
#include <vector>

#include <Eigen/Core>

namespace cosim::bench {

struct PourScene {
  double radius = 0.01;    // [m]
  double density = 2500;   // [kg/m^3], glass beads
  double friction = 0.5;
  double dt = 1e-3;        // [s]
  int steps = 500;
  int iterations = 10;     // contact-solver iterations per step (both engines)
  double margin = 0.002;   // [m]: pairs closer than this are contact candidates (both engines)
  double half_width = 0;   // the box is [-w, w]^2 x [0, inf)
  std::vector<Eigen::Vector3d> positions;
  std::vector<Eigen::Vector3d> velocities;
};

// A lattice of spacing 2.4 r (gaps of 0.4 r, so the column collapses with real impacts),
// about as tall as wide, with random horizontal velocities of up to 0.1 m/s (fixed seed).
PourScene pour(std::size_t n);

}  // namespace cosim::bench
