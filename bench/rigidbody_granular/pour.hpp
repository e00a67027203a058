// The poured-spheres scene both engines run: N equal spheres on a jittered lattice above
// the floor of an open box, falling and packing under gravity with frictional contacts.
#pragma once

#include <cstddef>
#include <vector>

#include <Eigen/Core>

namespace cosim::bench {

// Hertz-Mindlin material of the DEM engines (cosim's DEM solver and LIGGGHTS). Young's
// modulus is glass's 63 GPa reduced by four orders, as DEM practice does: its contact
// time (about 3 ms at 1 m/s) then spans tens of steps of 0.1 ms.
struct HertzMaterial {
  double young = 5e6;  // [Pa]
  double poisson = 0.25;
  double restitution = 0.5;  // normal coefficient; friction is the scene's
};

struct PourScene {
  double radius = 0.01;   // [m]
  double density = 2500;  // [kg/m^3], glass beads
  double friction = 0.5;
  double dt = 1e-3;       // [s]
  int steps = 500;        // of dt; the DEM engines cover the same time in steps of dem_dt
  int iterations = 10;    // contact-solver iterations per step (both engines)
  double margin = 0.002;  // [m]: pairs closer than this are contact candidates (both engines)
  double half_width = 0;  // the box is [-w, w]^2 x [0, inf)
  HertzMaterial hertz{};  // the DEM engines' contacts
  double dem_dt = 1e-4;   // [s]: the DEM engines' step, over the same time (steps * dt)
  std::vector<Eigen::Vector3d> positions;
  std::vector<Eigen::Vector3d> velocities;
};

// A lattice of spacing 2.4 r (gaps of 0.4 r, so the column collapses with real impacts),
// about as tall as wide, with random horizontal velocities of up to 0.1 m/s (fixed seed).
PourScene pour(std::size_t n);

// Steps of dem_dt over the scene's time.
int dem_steps(const PourScene& scene);
double sphere_mass(const PourScene& scene);
// Translational and rotational energy of one sphere [J].
double kinetic_energy(const PourScene& scene, const Eigen::Vector3d& velocity, const Eigen::Vector3d& angular_velocity);

}  // namespace cosim::bench
