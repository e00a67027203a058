// The soft step (Catto 2024, Box2D v3): soft contacts solved with bias before the positions
// move, then, after they moved, a rigid pass without bias (the relax) and restitution.
// Penetration is pushed out by a damped spring, not by real velocity, so the relax takes
// the push back out of the velocity the next step starts with. Small groups solve their
// impulses directly (contact_block.hpp), which makes the mass ratio irrelevant;
// see README.md "Soft step" for the choices.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "rigidbody/solver/contact_block.hpp"
#include "rigidbody/solver/contact_memory.hpp"
#include "rigidbody/solver/point_update.hpp"
#include "rigidbody/solver/problem.hpp"
#include "rigidbody/solver/softness.hpp"

namespace cosim::rigidbody::solver {

struct SoftOptions {
  // Contact spring: natural frequency around the group's whole dynamic mass, so that at
  // rest no point sinks more than g / (2 pi hertz)^2 (1 um at 500 Hz) under any load.
  // At most a quarter of the substep rate (Box2D's bound: the spring must be resolved):
  // 500 Hz with two substeps of a 1 ms dt.
  double hertz = 500.0;
  // The frequency the springs run at in substeps of h: hertz, capped.
  double spring_hertz(double h) const { return std::min(hertz, 0.25 / h); }
  double damping_ratio = 10.0;  // overdamped: penetration recedes without a bounce
  double push_speed = 3.0;      // [m/s] the fastest a penetration is pushed out
  int iterations = 2;           // sweeps with bias per substep, before the positions move
  int relax_iterations = 2;     // rigid sweeps per substep, after they moved
  // Substeps per narrow phase (Box2D's sub-stepping): the world's dt split into this many,
  // each solved, moved and relaxed on the contact points found at the dt's start. A pile's
  // overlap is its springs' sag, and substeps allow stiffer springs for the same sweeps
  // (bench/rigidbody_granular/README.md, "The soft step's settings").
  int substeps = 2;
  // Groups with at most block_points points solve their normal impulses at once (cost ~n^3
  // per factorization: one per pass and active set, kept over a dt's substeps). Friction passes a load through a light
  // body as slowly as Gauss-Seidel normals do, so groups with at most full_block_points points whose heaviest body is
  // more than full_block_mass_ratio times the lightest solve friction at once too (~(3n)^3).
  std::size_t block_points = 128;
  std::size_t full_block_points = 32;
  double full_block_mass_ratio = 10.0;
  double restitution_threshold = 0.1;  // [m/s]: slower impacts are inelastic (resting)
  FrictionModel friction = FrictionModel::cone;
  // Only for the report: the sweep counts are fixed (as Box2D's), and a pass's last sweep
  // is measured against this with the impulse solvers' test (README.md "Soft step").
  double tolerance = 1e-6;
};

class SoftStep {
 public:
  explicit SoftStep(const SoftOptions& options = {}) : options_(options) {}
  const SoftOptions& options() const { return options_; }

  // Before the positions move: warm start from `memory` (one per point), then the soft
  // sweeps with bias. Keeps the rows for relax(). Reports the biased sweeps and how much
  // the last one still changed.
  SolveReport solve(const ContactScene& scene, std::span<const CachedContact> memory);
  // A further substep on the rows solve() built (no narrow phase): warm start from the
  // last substep's impulses, the sweeps with bias on the separations it left. After a
  // relax() that was `last` there are no rows: solve() first.
  SolveReport solve_again(std::span<dynamics::BodyState> states);
  // After the positions moved with the solve's velocities: rigid sweeps without bias on the
  // separations those velocities left (no new narrow phase). After the last substep of a
  // narrow phase (`last`), restitution, and the impulses go to `memory` for the next
  // step's warm start. Reports all sweeps of the substep (the solve's and these) and how
  // much the last relax sweep still changed.
  SolveReport relax(std::span<dynamics::BodyState> states, std::span<CachedContact> memory, bool last);

 private:
  struct Row {
    std::uint32_t point = 0;
    ContactFrame frame;
    PointLaw law;
    Eigen::Vector3d impulse = Eigen::Vector3d::Zero();
    double separation = 0.0;  // at the narrow phase; after each substep's solve, at its end
    double approach = 0.0;    // normal velocity before the first substep's solve, for restitution
    double restitution = 0.0;
  };
  struct Group {
    std::size_t first = 0;  // rows
    std::size_t count = 0;
    Softness soft;
    bool per_point = false;  // compliance relative to each point's W_nn, not the group's mass
    int axes = 1;            // rows per point solved at once: 3, 1 (normals) or 0 (Gauss-Seidel)
    // The largest normal velocity change a point needs at the substep's start,
    // max(0, target - u_n) with the biased target: what the report's residual is relative to.
    double scale = 0.0;
    // A directly solved group's block for the biased pass [1] and the relax [0], kept over
    // the substeps of a narrow phase: the same rows and, unless a gap closed, the same
    // compliance, so the same matrix and (for the same active set) factorization. Out of
    // line, so that a group's place in groups_, whose capacity outlives the groups (a pile
    // has about one group per body), stays small (bench/rigidbody_granular/README.md
    // "Where the memory goes").
    struct Block {
      std::vector<double> compliance;
      std::optional<ContactBlock> solver;
    };
    std::unique_ptr<std::array<Block, 2>> blocks;
  };

  void build_rows(const ContactScene& scene, std::span<const CachedContact> memory);
  // Sweeps over every group: with bias and soft (solve) or rigid without bias (relax).
  // Residual: the last sweep's largest velocity_change at a point over its group's scale.
  SolveReport pass(std::span<dynamics::BodyState> states, bool biased, int count);
  std::pair<double, double> normal_law(const Group& g, const Row& r, bool biased) const;
  // Returns the last sweep's largest velocity_change at a point.
  double sweeps(Group& g, bool biased, std::span<dynamics::BodyState> states, std::span<const double> target,
                std::span<const double> compliance, int count);
  void set_impulse(Row& r, const Eigen::Vector3d& impulse, std::span<dynamics::BodyState> states) const;
  void restitution(std::span<dynamics::BodyState> states);

  SoftOptions options_;
  double dt_ = 0.0;
  std::span<const Mobility> mobility_;
  std::vector<Row> rows_;
  std::vector<Group> groups_;
};

}  // namespace cosim::rigidbody::solver
