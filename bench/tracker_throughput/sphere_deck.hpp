#pragma once
// SPARTA's `sphere` deck as docs/references.md describes it, with a CSG ball for SPARTA's 1200
// triangles: a box [-5,5]^3 m of 22^3 cells, open on every side, argon streaming at 2500 m/s
// and 300 K (n = 7.03e18 m^-3) entering through every face, VSS collisions, a unit sphere
// at the centre re-emitting diffusely at 300 K, dt 1e-5 s. The step is cosim-tracker's
// (Simulation::step, tracker/step): sort by cell, collide, move, inject.

#include "tracker/step/collide.hpp"
#include "tracker/tracking/inflow.hpp"

#include <memory>

namespace cosim::bench {

struct SphereDeck {
  static constexpr double kHalfSide = 5.0;       // m
  static constexpr int kCells = 22;              // per side
  static constexpr double kRadius = 1.0;         // m, at the origin
  static constexpr double kSpeed = 2500.0;       // m/s along +x
  static constexpr double kTemperature = 300.0;  // K, the stream's and the wall's
  static constexpr double kDensity = 7.03e18;    // m^-3
  static constexpr double kDt = 1e-5;            // s
  // Real molecules per simulator, chosen for SPARTA's 106,000 simulators in the steady flow.
  // The undisturbed stream would hold n (V_box - V_ball) / fnum = 102,000 of them; the flow
  // around the ball holds about 4 % more (molecules re-emitted at 300 K linger in front of
  // it and in its wake), so configs/tracker-sphere-stream.yaml's 6.63e16 gives 109,800.
  static constexpr double kWeight = 6.86e16;

  // Untimed steps from the seeded uniform stream to the steady flow around the ball: the
  // count settles after 1.5 box crossings (+2.2 % after 400 steps, +4.0 after 600, +4.2
  // after 800 and after 1000).
  int warm_up = 600;
  int steps = 1000;  // timed
};

// The mesh, the open walls, the ball and the stream; the Domain, the obstacle and the
// inflow keep a reference to the mesh, so they live together (and the box does not move).
struct SphereBox {
  SphereBox();
  SphereBox(const SphereBox&) = delete;
  tracker::mesh::Mesh mesh;
  tracker::step::Collisions collisions;  // VSS argon from the species file
  double mass;                           // argon's, the collision model's
  std::unique_ptr<tracker::tracking::Domain> domain;
  tracker::tracking::Obstacles sphere;
  std::unique_ptr<tracker::tracking::Inflow> inflow;

  // Simulators of the undisturbed stream in the box outside the ball: n (V - V_ball) / fnum.
  static double stream_count();
  // The free-molecular drag on the ball, N (Bird's closed form, wall at the gas temperature).
  double free_molecular_drag() const;
};

struct SphereResult {
  long long seeded = 0, timed_from = 0, particles = 0;  // at the start of the warm-up, of the timed steps, at the end
  double seconds = 0.0, cpu_seconds = 0.0;              // the timed steps: sort, collisions, moves, inflow
  tracker::tracking::MoveTally tally;                   // the timed steps (the inflow's partial moves included)
  long long collisions = 0;                             // the timed steps'
  long long lost = 0;                       // is_lost at the end, plus those the tracking counted lost in any step
  long long outside = 0;                    // outside their cell by more than the tolerance at the end
  tracker::tracking::ObstacleTally sphere;  // the timed steps'
  double drag = 0.0;                        // N along the stream over the timed steps

  double moves_per_second() const { return static_cast<double>(tally.moves) / seconds; }
  double moves_per_cpu_second() const { return static_cast<double>(tally.moves) / cpu_seconds; }
  double collisions_per_move() const { return static_cast<double>(collisions) / static_cast<double>(tally.moves); }
};

// Seeds the box with the stream's drifting Maxwellian outside the ball, runs the warm-up and
// times deck.steps steps.
SphereResult run_sphere(const SphereBox& box, const SphereDeck& deck);

}  // namespace cosim::bench
