// Advancing a set of rigid bodies over one coupling window, substep by substep.
#pragma once

#include <span>
#include <vector>

#include "rigidbody/dynamics/added_inertia.hpp"
#include "rigidbody/dynamics/body.hpp"
#include "rigidbody/dynamics/body_forces.hpp"

namespace cosim::rigidbody::dynamics {

enum class Scheme {
  semi_implicit_euler,  // first order, implicit gyroscopic term; the default (semi_implicit_euler.hpp)
  leapfrog,             // second order, symplectic, conserves angular momentum (leapfrog.hpp)
};

struct IntegratorSettings {
  Scheme scheme = Scheme::semi_implicit_euler;
  double dt = 1e-3;  // the longest substep; the window is split into ceil((t1 - t0) / dt) >= 1 equal ones
  BodyForces body_forces;
};

// A window [t0, t1] split into equal substeps, each integrated in two halves: every body's
// velocity, then every body's position with the velocities the states then hold. Between
// the halves a caller may change velocities (the world's contact solver does), after them
// too (the soft step's relax). `inertia` is parallel to `states`; `external` is either
// parallel to it (the coupler's wrench per body, see WindowWrench) or empty (none); so is
// `liquid` (bodies moving with a liquid, with_added; empty: none is).
// Fixed bodies (inverse_mass == 0) are not touched, not even by velocities set between the
// halves; translation-only bodies (rotates == false) keep their orientation and angular
// velocity.
class Substeps {
 public:
  // Throws std::invalid_argument for mismatched spans, t1 < t0 or dt <= 0.
  Substeps(std::span<BodyState> states, std::span<const BodyInertia> inertia, std::span<const WindowWrench> external,
           double t0, double t1, const IntegratorSettings& settings, std::span<const InLiquid> liquid = {});

  long count() const { return count_; }  // 0 for an empty window
  double length() const { return length_; }
  // Substep k's first half: gravity, buoyancy and the wrench at the substep's start
  // (leapfrog: its midpoint).
  void integrate_velocities(long k);
  // The second half of the substep whose velocities were integrated last.
  void integrate_positions();

 private:
  std::span<BodyState> states_;
  std::span<const BodyInertia> inertia_;
  std::span<const WindowWrench> external_;
  std::span<const InLiquid> liquid_;
  double t0_, t1_;
  Scheme scheme_;
  long count_;
  double length_;
  std::vector<Eigen::Vector3d> acceleration_;  // body forces' per body
  std::vector<BodyState> start_;               // leapfrog's: every body's state before the velocity half
  std::vector<std::size_t> held_;              // fixed or translation-only bodies
  // Their states before the velocity half, parallel to held_: semi-implicit Euler keeps no
  // copy of the others (112 bytes a body, bench/rigidbody_granular/README.md "Where the
  // memory goes").
  std::vector<BodyState> held_start_;
};

// Moves `states` from t0 to t1 with nothing between the halves: free flight under the
// body forces, `external` and `liquid`. Throws as Substeps does.
void advance(std::span<BodyState> states, std::span<const BodyInertia> inertia, std::span<const WindowWrench> external,
             double t0, double t1, const IntegratorSettings& settings, std::span<const InLiquid> liquid = {});

}  // namespace cosim::rigidbody::dynamics
