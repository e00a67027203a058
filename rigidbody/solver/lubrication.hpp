// The liquid film between two surfaces closer than the fluid's grid resolves. Its normal
// force, to leading order in the gap s (Brenner 1961 for a sphere against a plane; Jeffrey
// 1982 for two spheres), is 6 pi mu R^2 v_n / s with R = R_a R_b / (R_a + R_b) and v_n the
// speed at which the gap closes (or opens: the film resists both). A coupled fluid already
// gives the part its grid resolves, so only the correction
//   F = 6 pi mu R^2 v_n (1 / max(s, roughness) - 1 / range),   s < range,
// is added, as resolved-particle codes do (Costa, Boersma, Westerweel & Breugem, Phys. Rev. E
// 92 (2015) 053012): it vanishes at `range`, so the
// force stays continuous as a body comes near, and it stops growing at `roughness`, where
// real surfaces touch. It brings a body arriving at a wall to rest over the last cell
// instead of at one contact impulse.
#pragma once

#include <span>

#include "rigidbody/solver/problem.hpp"

namespace cosim::rigidbody::solver {

struct LubricationOptions {
  double viscosity = 0.0;  // mu of the liquid [Pa s]; 0: no film force
  double range = 0.0;      // the gap below which the fluid does not resolve the film [m]
  double roughness = 0.0;  // the gap at which the force stops growing [m]
  bool active() const { return viscosity > 0.0; }
};

// Applies the film's impulse over scene.dt to the closest point of each contact pair,
// implicitly in the normal relative velocity (the damping 6 pi mu R^2 / s grows without
// bound as s falls, so an explicit update would overshoot). `radii` holds each body's
// radius of curvature (infinite for a plane).
void apply_lubrication(const ContactScene& scene, std::span<const double> radii, const LubricationOptions& options);

}  // namespace cosim::rigidbody::solver
