#include "rigidbody/solver/impulse_solver.hpp"

#include <algorithm>
#include <vector>

#include "rigidbody/solver/contact_frame.hpp"
#include "rigidbody/solver/contact_groups.hpp"

namespace cosim::rigidbody::solver {

ImpulseOptions ImpulseOptions::projected_gauss_seidel() {
  ImpulseOptions o;
  o.warm_start = false;
  return o;
}

ImpulseOptions ImpulseOptions::projected_jacobi() {
  ImpulseOptions o;
  o.schedule = Schedule::jacobi;
  o.warm_start = false;
  o.max_iterations = 200;
  return o;
}

ImpulseOptions ImpulseOptions::sequential_impulses() { return {}; }

namespace {

struct Row {
  std::uint32_t point = 0;  // index into the ContactSet's points and the memory
  ContactFrame frame;
  PointLaw law;
  double restitution = 0.0;
  double share = 1.0;  // Jacobi damping, see ImpulseOptions::relaxation
  Eigen::Vector3d impulse = Eigen::Vector3d::Zero();
  // Normal velocity the solve must add here: target minus the velocity before it, if positive.
  double demand = 0.0;
};

class GroupSolver {
 public:
  GroupSolver(const ContactScene& scene, std::span<const int> points_on, const ImpulseOptions& options)
      : scene_(scene), points_on_(points_on), options_(options) {}

  SolveReport solve(std::span<const std::uint32_t> pairs, std::span<CachedContact> memory) {
    build_rows(pairs, memory);
    if (options_.restitution == Restitution::sequential) resolve_impacts();
    for (const Row& r : rows_) r.frame.apply_local(r.impulse, scene_.states, scene_.mobility);

    // The group's velocity scale: the largest normal velocity change any of its points needs.
    // A contact inside a resting stack needs none itself (its bodies fell alike) but carries
    // the weight above it, so each point is measured against the group's scale, in velocity
    // units, which are the same for a light body as for a heavy one (README.md).
    double scale = 0.0;
    for (const Row& r : rows_) scale = std::max(scale, r.demand);
    SolveReport report;
    report.converged = false;
    while (report.iterations < options_.max_iterations && !report.converged) {
      ++report.iterations;
      const double change = options_.schedule == Schedule::jacobi ? jacobi_sweep() : gauss_seidel_sweep();
      // Nothing to do (scale 0): only an unchanged sweep has converged.
      report.residual = change == 0.0 ? 0.0 : change / scale;
      report.converged = report.residual <= options_.tolerance;
    }
    for (const Row& r : rows_)
      memory[r.point] = {.normal = r.impulse[0],
                         .tangential = r.frame.basis.bottomRows<2>().transpose() * r.impulse.tail<2>()};
    return report;
  }

 private:
  void build_rows(std::span<const std::uint32_t> pairs, std::span<const CachedContact> memory) {
    const double dt = scene_.dt;
    for (const std::uint32_t i : pairs) {
      const contact::PairContacts& m = scene_.contacts.pairs[i];
      const Material& material = scene_.materials[i];
      for (std::uint32_t k = m.first; k < m.first + m.count; ++k) {
        const contact::ContactPoint& p = scene_.contacts.points[k];
        Row r;
        r.point = k;
        r.frame = make_frame(m, p, scene_.states);
        r.restitution = material.restitution;
        r.law = {.response = r.frame.local_response(scene_.mobility),
                 .target_normal_velocity = position_bias(p.distance),
                 .friction = material.friction,
                 .model = options_.friction};
        const double approach = r.frame.local_velocity(scene_.states)[0];
        // Bounce only off points that actually close during this step, so a speculative
        // contact does not bounce a body before it arrives.
        const bool impact = approach < -options_.restitution_threshold && p.distance + dt * approach <= 0.0;
        if (options_.restitution == Restitution::simultaneous && impact)
          r.law.target_normal_velocity = std::max(r.law.target_normal_velocity, -r.restitution * approach);
        r.demand = std::max(0.0, r.law.target_normal_velocity - approach);
        if (options_.warm_start) {
          const CachedContact& c = memory[k];
          r.impulse = {c.normal, r.frame.basis.row(1).dot(c.tangential), r.frame.basis.row(2).dot(c.tangential)};
        }
        rows_.push_back(r);
      }
    }
    const auto load = [&](std::uint32_t body) { return scene_.inertias[body].is_fixed() ? 1 : points_on_[body]; };
    for (Row& r : rows_) r.share = options_.relaxation / std::max(load(r.frame.a), load(r.frame.b));
  }

  // Speculative gaps may close within the step; penetration beyond the slop is pushed
  // out by a fraction erp per step (Baumgarte).
  double position_bias(double distance) const {
    if (distance > 0.0) return -distance / scene_.dt;
    return options_.erp * std::max(0.0, -distance - options_.slop) / scene_.dt;
  }

  // Restitution::sequential. Each firing is a complete two-body impact with the current
  // velocities, so with e = 1 every one conserves energy exactly.
  void resolve_impacts() {
    for (int sweep = 0; sweep < options_.max_iterations; ++sweep) {
      bool fired = false;
      for (const Row& r : rows_) {
        if (r.restitution <= 0.0) continue;
        const double un = r.frame.local_velocity(scene_.states)[0];
        if (un >= -options_.restitution_threshold) continue;
        const double impulse = -(1.0 + r.restitution) * un / r.law.response(0, 0);
        r.frame.apply_local(Eigen::Vector3d(impulse, 0.0, 0.0), scene_.states, scene_.mobility);
        fired = true;
      }
      if (!fired) return;
    }
  }

  // Both sweeps return the largest velocity_change over the group's points.
  double gauss_seidel_sweep() {
    double change = 0.0;
    for (Row& r : rows_) {
      const Eigen::Vector3d next = update_point(r.law, r.frame.local_velocity(scene_.states), r.impulse);
      const Eigen::Vector3d delta = next - r.impulse;
      r.frame.apply_local(delta, scene_.states, scene_.mobility);
      r.impulse = next;
      change = std::max(change, velocity_change(r.law, delta));
    }
    return change;
  }

  double jacobi_sweep() {
    proposals_.resize(rows_.size());
    for (std::size_t i = 0; i < rows_.size(); ++i)
      proposals_[i] = update_point(rows_[i].law, rows_[i].frame.local_velocity(scene_.states), rows_[i].impulse);
    double change = 0.0;
    for (std::size_t i = 0; i < rows_.size(); ++i) {
      Row& r = rows_[i];
      // A convex combination of two feasible impulses stays feasible: no re-projection.
      const Eigen::Vector3d delta = r.share * (proposals_[i] - r.impulse);
      r.frame.apply_local(delta, scene_.states, scene_.mobility);
      r.impulse += delta;
      change = std::max(change, velocity_change(r.law, delta));
    }
    return change;
  }

  const ContactScene& scene_;
  std::span<const int> points_on_;  // contact points per body, all groups
  const ImpulseOptions& options_;
  std::vector<Row> rows_;
  std::vector<Eigen::Vector3d> proposals_;
};

}  // namespace

SolveReport solve_impulses(const ContactScene& scene, std::span<CachedContact> memory, const ImpulseOptions& options) {
  std::vector<int> points_on(scene.states.size(), 0);
  for (const auto& m : scene.contacts.pairs) {
    points_on[m.a] += static_cast<int>(m.count);
    points_on[m.b] += static_cast<int>(m.count);
  }
  SolveReport total;
  for (const auto& group : contact_groups(scene.inertias, scene.contacts.pairs)) {
    const SolveReport r = GroupSolver(scene, points_on, options).solve(group, memory);
    total.iterations = std::max(total.iterations, r.iterations);
    total.residual = std::max(total.residual, r.residual);
    total.converged = total.converged && r.converged;
  }
  return total;
}

}  // namespace cosim::rigidbody::solver
