#include "rigidbody/solver/soft_step.hpp"

#include <algorithm>
#include <limits>
#include <optional>
#include <utility>

#include "rigidbody/contact/room.hpp"
#include "rigidbody/solver/contact_block.hpp"
#include "rigidbody/solver/contact_groups.hpp"

namespace cosim::rigidbody::solver {

namespace {

// The relax is rigid; a direct solve still needs a little compliance, since four coplanar
// points of a box face hold only three degrees of freedom (any split of the load is a solution).
constexpr double kRigidCompliance = 1e-6;  // relative to the row's own W_kk

}  // namespace

void SoftStep::build_rows(const ContactScene& scene, std::span<const CachedContact> memory) {
  rows_.clear();
  groups_.clear();
  const std::vector<std::vector<std::uint32_t>> groups = contact_groups(scene.inertias, scene.contacts.pairs);
  contact::make_room(rows_, scene.contacts.points.size());
  contact::make_room(groups_, groups.size());
  std::vector<char> counted(scene.states.size(), 0);
  for (const auto& pairs : groups) {
    Group g;
    g.first = rows_.size();
    double mass = 0.0, lightest = std::numeric_limits<double>::infinity(), heaviest = 0.0;
    for (const std::uint32_t i : pairs) {
      const contact::PairContacts& m = scene.contacts.pairs[i];
      for (const std::uint32_t body : {m.a, m.b})
        if (!scene.inertias[body].is_fixed() && !counted[body]) {
          counted[body] = 1;
          const double body_mass = 1.0 / scene.inertias[body].inverse_mass;
          mass += body_mass;
          lightest = std::min(lightest, body_mass);
          heaviest = std::max(heaviest, body_mass);
        }
      for (std::uint32_t k = m.first; k < m.first + m.count; ++k) {
        const contact::ContactPoint& p = scene.contacts.points[k];
        Row r;
        r.point = k;
        r.frame = make_frame(m, p, scene.states);
        r.law = {.response = r.frame.local_response(scene.mobility),
                 .friction = scene.materials[i].friction,
                 .model = options_.friction};
        r.separation = p.distance;
        r.approach = r.frame.local_velocity(scene.states)[0];
        r.restitution = scene.materials[i].restitution;
        const CachedContact& c = memory[k];
        r.impulse = {c.normal, r.frame.basis.row(1).dot(c.tangential), r.frame.basis.row(2).dot(c.tangential)};
        rows_.push_back(r);
      }
    }
    for (const Row& r : std::span(rows_).subspan(g.first)) counted[r.frame.a] = counted[r.frame.b] = 0;
    g.count = rows_.size() - g.first;
    // A direct solve takes any stiffness, so its springs are as stiff as the whole group is
    // heavy. Gauss-Seidel converges in a few sweeps only if each point's compliance is of
    // the order of its own W_nn (Box2D's choice): a unit mass here, times W_nn per point.
    g.per_point = g.count > options_.block_points;
    const bool mass_ratio = heaviest > options_.full_block_mass_ratio * lightest;
    g.axes = g.per_point ? 0 : g.count <= options_.full_block_points && mass_ratio ? 3 : 1;
    g.soft = make_softness(options_.spring_hertz(scene.dt), options_.damping_ratio, g.per_point ? 1.0 : mass, scene.dt);
    groups_.push_back(std::move(g));
  }
}

SolveReport SoftStep::solve(const ContactScene& scene, std::span<const CachedContact> memory) {
  dt_ = scene.dt;
  mobility_ = scene.mobility;
  build_rows(scene, memory);
  return solve_again(scene.states);
}

// Each substep applies its impulses anew: the velocities it starts from carry the last
// substep's contact impulses, but not the one that holds against this substep's gravity.
SolveReport SoftStep::solve_again(std::span<dynamics::BodyState> states) {
  // What the report's residual is relative to, for this substep: a gap that closes only in
  // a later substep has work to do there, not in the first.
  for (Group& g : groups_) {
    g.scale = 0.0;
    for (const Row& r : std::span(rows_).subspan(g.first, g.count))
      g.scale = std::max(g.scale, normal_law(g, r, true).first - r.frame.local_velocity(states)[0]);
  }
  for (Row& r : rows_) {
    const Eigen::Vector3d warm = r.impulse;
    r.impulse.setZero();
    set_impulse(r, warm, states);
  }
  const SolveReport report = pass(states, true, options_.iterations);
  // Where the positions will be after this substep, to first order in dt: the relative
  // velocity at the point, not the motion of a point fixed on each body, which on a
  // rolling sphere would open a gap that is not there.
  for (Row& r : rows_) r.separation += dt_ * r.frame.local_velocity(states)[0];
  return report;
}

SolveReport SoftStep::relax(std::span<dynamics::BodyState> states, std::span<CachedContact> memory, bool last) {
  SolveReport report = pass(states, false, options_.relax_iterations);
  if (!groups_.empty()) report.iterations += options_.iterations;
  if (!last) return report;
  restitution(states);
  for (const Row& r : rows_)
    memory[r.point] = {.normal = r.impulse[0],
                       .tangential = r.frame.basis.bottomRows<2>().transpose() * r.impulse.tail<2>()};
  // The rows and the groups' blocks (matrices, factorizations) serve this narrow phase's
  // substeps only: none is held between steps, and no substep follows without a solve().
  rows_.clear();
  groups_.clear();
  return report;
}

// What a sweep asks of a row's normal: the velocity to reach and the compliance.
std::pair<double, double> SoftStep::normal_law(const Group& g, const Row& r, bool biased) const {
  if (!biased) return {std::min(0.0, -r.separation / dt_), kRigidCompliance * r.law.response(0, 0)};
  // A gap may close within the step (speculative, rigid); a penetration is a spring.
  if (r.separation > 0.0) return {-r.separation / dt_, 0.0};
  return {std::min(-g.soft.bias_rate * r.separation, options_.push_speed),
          g.soft.compliance * (g.per_point ? r.law.response(0, 0) : 1.0)};
}

SolveReport SoftStep::pass(std::span<dynamics::BodyState> states, bool biased, int count) {
  SolveReport report{.iterations = groups_.empty() ? 0 : count};
  std::vector<double> target;
  std::vector<double> compliance;
  for (Group& g : groups_) {
    target.clear();
    compliance.clear();
    for (const Row& r : std::span(rows_).subspan(g.first, g.count)) {
      const auto [velocity, give] = normal_law(g, r, biased);
      target.push_back(velocity);
      compliance.push_back(give);
    }
    const double change = sweeps(g, biased, states, target, compliance, count);
    // As the impulse solvers: with nothing to do (scale 0) only an unchanged sweep settled.
    report.residual = std::max(report.residual, change == 0.0 ? 0.0 : change / g.scale);
  }
  report.converged = report.residual <= options_.tolerance;
  return report;
}

// A group with a large mass ratio solves every row at once (friction sticking, sliding
// points point by point); a small or middle-sized group solves friction point by point, then
// the normals at once; a large one all point by point (Gauss-Seidel).
double SoftStep::sweeps(Group& g, bool biased, std::span<dynamics::BodyState> states, std::span<const double> target,
                        std::span<const double> compliance, int count) {
  const std::span<Row> rows = std::span(rows_).subspan(g.first, g.count);
  const int axes = g.axes;
  ContactBlock* block = nullptr;
  std::vector<double> row_target;
  if (axes > 0) {
    std::vector<double> row_compliance;
    for (std::size_t i = 0; i < rows.size(); ++i)
      for (int axis = 0; axis < axes; ++axis) {
        row_target.push_back(axis == 0 ? target[i] : 0.0);
        // Friction is rigid; its rows get the relax's regularization.
        row_compliance.push_back(axis == 0 ? compliance[i] : kRigidCompliance * rows[i].law.response(axis, axis));
      }
    if (!g.blocks) g.blocks = std::make_unique<std::array<Group::Block, 2>>();
    Group::Block& kept = (*g.blocks)[biased ? 1 : 0];
    if (!kept.solver || kept.compliance != row_compliance) {
      std::vector<ContactFrame> frames;
      for (const Row& r : rows) frames.push_back(r.frame);
      kept.solver.emplace(frames, axes, mobility_, row_compliance);
      kept.compliance = std::move(row_compliance);
    }
    block = &*kept.solver;
  }
  std::vector<double> u(row_target.size());
  std::vector<double> lambda(row_target.size());
  const auto solve_block = [&] {
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const Eigen::Vector3d v = rows[i].frame.local_velocity(states);
      for (int axis = 0; axis < axes; ++axis) {
        u[i * axes + axis] = v[axis];
        lambda[i * axes + axis] = rows[i].impulse[axis];
      }
    }
    block->solve(u, row_target, lambda);
  };
  std::vector<Eigen::Vector3d> last;  // the impulses before the last sweep
  for (int sweep = 0; sweep < count; ++sweep) {
    if (sweep == count - 1)
      for (const Row& r : rows) last.push_back(r.impulse);
    if (!block) {
      // Normal, then friction on the velocity the normal change leaves (through the point's
      // own W, as update_point): one velocity and one application per point and sweep.
      for (std::size_t i = 0; i < rows.size(); ++i) {
        Row& r = rows[i];
        const Eigen::Vector3d u = r.frame.local_velocity(states);
        Eigen::Vector3d next = r.impulse;
        next[0] = std::max(0.0, r.impulse[0] + (target[i] - u[0] - compliance[i] * r.impulse[0]) /
                                                   (r.law.response(0, 0) + compliance[i]));
        const Eigen::Vector3d after_normal = u + r.law.response.col(0) * (next[0] - r.impulse[0]);
        set_impulse(r, update_friction(r.law, after_normal, next), states);
      }
      continue;
    }
    if (axes == 1)
      for (Row& r : rows) set_impulse(r, update_friction(r.law, r.frame.local_velocity(states), r.impulse), states);
    solve_block();
    // A point the block would hold with more friction than mu allows slides: it gets a
    // point update instead, whose cone step opposes the slip (capping the block's sticking
    // impulse would not, and could push the body along).
    std::vector<std::size_t> sliding;
    for (std::size_t i = 0; i < rows.size(); ++i) {
      Eigen::Vector3d next = rows[i].impulse;
      for (int axis = 0; axis < axes; ++axis) next[axis] = lambda[i * axes + axis];
      if (axes == 3 && cap_friction(rows[i].law, next) != next) {
        next.tail<2>() = rows[i].impulse.tail<2>();
        sliding.push_back(i);
      }
      set_impulse(rows[i], next, states);
    }
    for (const std::size_t i : sliding)
      set_impulse(rows[i], update_friction(rows[i].law, rows[i].frame.local_velocity(states), rows[i].impulse), states);
  }
  double change = 0.0;
  for (std::size_t i = 0; i < last.size(); ++i)
    change = std::max(change, velocity_change(rows[i].law, rows[i].impulse - last[i]));
  return change;
}

void SoftStep::set_impulse(Row& r, const Eigen::Vector3d& impulse, std::span<dynamics::BodyState> states) const {
  r.frame.apply_local(impulse - r.impulse, states, mobility_);
  r.impulse = impulse;
}

// After the relax, as Box2D: a point that approached faster than the threshold before the
// solve and carries load leaves at e times that speed (one sweep).
void SoftStep::restitution(std::span<dynamics::BodyState> states) {
  for (Row& r : rows_) {
    if (r.restitution <= 0.0 || r.approach > -options_.restitution_threshold || r.impulse[0] <= 0.0) continue;
    const double un = r.frame.local_velocity(states)[0];
    const double next = std::max(0.0, r.impulse[0] + (-r.restitution * r.approach - un) / r.law.response(0, 0));
    set_impulse(r, {next, r.impulse[1], r.impulse[2]}, states);
  }
}

}  // namespace cosim::rigidbody::solver
