// A World's step, per substep: integrate velocities -> broad phase -> narrow phase -> solve
// contacts -> integrate positions (-> relax contacts, the soft step), each stage timed into
// the StepReport. The soft step's further substeps of a dt skip the broad and narrow phase.
#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "rigidbody/contact/room.hpp"
#include "rigidbody/dynamics/integrator.hpp"
#include "rigidbody/world/world.hpp"

namespace cosim::rigidbody::world {

namespace {

broadphase::Object object_of(std::uint32_t id, const geometry::Shape& shape, const dynamics::BodyState& s, bool fixed) {
  broadphase::Object o{.id = id, .centre = s.position, .fixed = fixed};
  if (const auto* wall = std::get_if<geometry::HalfSpace>(&shape)) {
    // geometry's {n . x <= 0} in the body frame is {R n . x <= R n . p} in the world.
    const Eigen::Vector3d n = s.orientation * wall->normal();
    o.infinite = true;
    o.half_space = broadphase::HalfSpace{n, n.dot(s.position)};
  } else if (std::holds_alternative<geometry::Container>(shape)) {
    o.infinite = true;  // its wall may meet any body inside it
  } else {
    o.radius = geometry::bounding_radius(shape);
  }
  return o;
}

// The step reports the worst substep.
void merge(StepReport& report, const solver::SolveReport& solved) {
  report.solver_iterations = std::max(report.solver_iterations, solved.iterations);
  report.residual = std::max(report.residual, solved.residual);
  report.converged = report.converged && solved.converged;
}

}  // namespace

StepReport World::advance(double window, std::span<const dynamics::WindowWrench> external,
                          std::span<const dynamics::AddedInertia> added) {
  const auto start = std::chrono::steady_clock::now();
  StepReport report;
  stepping_ = inertias_;
  std::span<const dynamics::InLiquid> liquid;
  if (!added.empty()) {
    if (added.size() != size()) throw std::invalid_argument("advance: added inertia must be one per body or none");
    moving_.resize(size());
    liquid_.resize(size());
    for (std::size_t i = 0; i < size(); ++i) {
      const dynamics::WithLiquid moving = dynamics::with_added(inertias_[i], added[i], states_[i].orientation);
      moving_[i] = moving.inertia;
      liquid_[i] = moving.liquid;
    }
    stepping_ = moving_;
    liquid = liquid_;
  }
  // "Only what the scene needs": without contacts (or with nothing to collide with) no
  // broad or narrow phase is ever called.
  const bool contacts = settings_.contact && size() > 1;
  const bool relax = contacts && settings_.solver == SolverKind::soft;
  // The soft step's substeps share their dt's narrow phase (solver/README.md "Soft step"),
  // unless the lubrication film needs each substep's own gaps.
  const int split = relax ? soft_.options().substeps : 1;
  const int collide_every = settings_.lubrication.active() ? 1 : split;
  dynamics::Substeps substeps(states_, stepping_, external, time_, time_ + window,
                              {dynamics::Scheme::semi_implicit_euler, settings_.dt / split, settings_.body_forces},
                              liquid);
  // A window shorter than dt has fewer substeps than a narrow phase covers.
  if (contacts) check_tunnelling(window, substeps.length() * std::min<long>(collide_every, substeps.count()), report);
  StageClock clock(report.seconds);
  for (long k = 0; k < substeps.count(); ++k) {
    ++report.substeps;
    substeps.integrate_velocities(k);
    clock.lap(Stage::integrate_velocities);
    if (contacts && k % collide_every == 0) {
      broad_phase(report);
      clock.lap(Stage::broad_phase);
      narrow_phase(report);
      clock.lap(Stage::narrow_phase);
      solve_contacts(substeps.length(), report);
      clock.lap(Stage::solve_contacts);
    } else if (contacts) {
      merge(report, soft_.solve_again(states_));
      clock.lap(Stage::solve_contacts);
    }
    // With the velocities the solver left: what semi-implicit Euler gives the solvers.
    substeps.integrate_positions();
    clock.lap(Stage::integrate_positions);
    if (relax) {
      relax_contacts(report, k % collide_every == collide_every - 1 || k == substeps.count() - 1);
      clock.lap(Stage::relax_contacts);
    }
  }
  time_ += window;
  report.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

void World::broad_phase(StepReport& report) {
  grid_.update(states_.size(), [this](std::size_t n) {
    const auto i = static_cast<std::uint32_t>(n);
    return object_of(i, shapes_[i], states_[i], inertias_[i].is_fixed());
  });
  // About as many pairs as last time, in a list of their own that becomes the edges.
  std::vector<broadphase::Pair> pairs;
  contact::make_room(pairs, graph_.edges().size());
  grid_.find_pairs(pairs);
  ++report.broadphase_updates;
  graph_.update(std::move(pairs));
}

void World::narrow_phase(StepReport& report) {
  const double margin = this->margin();
  contact::ContactSet& contacts = graph_.contacts();
  contacts.clear();
  // A sphere pair has one point: other shapes take the points past this.
  contact::make_room(contacts.pairs, graph_.edges().size());
  contact::make_room(contacts.points, graph_.edges().size());
  for (const auto& [a, b] : graph_.edges()) {
    contact::Manifold m{.a = a, .b = b};
    const geometry::Pose pa(states_[a].position, states_[a].orientation);
    const geometry::Pose pb(states_[b].position, states_[b].orientation);
    narrowphase::collide(shapes_[a], pa, shapes_[b], pb, margin, m, mesh_maps_);
    contacts.add(m);
  }
  report.pairs_tested += graph_.edges().size();
  report.contacts = contacts.points.size();

  pair_materials_.clear();
  contact::make_room(pair_materials_, contacts.pairs.size());
  for (const contact::PairContacts& p : contacts.pairs)
    pair_materials_.push_back(combine(materials_[p.a], materials_[p.b]));
}

solver::SolveReport World::solve(const solver::ContactScene& scene, std::span<solver::CachedContact> memory) {
  switch (settings_.solver) {
    case SolverKind::soft:
      return soft_.solve(scene, memory);
    case SolverKind::dem:
      return solver::solve_dem(scene, memory, settings_.dem);
    default:
      return solver::solve_impulses(scene, memory, settings_.impulse_options());
  }
}

void World::solve_contacts(double dt, StepReport& report) {
  // The solvers split the pairs into contact groups themselves (solver::contact_groups:
  // components linked through dynamic bodies only) and report the worst group.
  mobility_ = solver::mobilities(states_, stepping_);
  const solver::ContactScene scene{states_, stepping_, mobility_, graph_.contacts(), pair_materials_, dt};
  // Before the contacts, so the solver sees the velocities the film has left.
  solver::apply_lubrication(scene, radii_, settings_.lubrication);
  const std::span<solver::CachedContact> memory = graph_.recall();
  merge(report, solve(scene, memory));
  // The soft step remembers after its relax, once the positions moved.
  if (settings_.solver != SolverKind::soft) graph_.remember();
}

void World::relax_contacts(StepReport& report, bool last) {
  merge(report, soft_.relax(states_, graph_.recalled(), last));
  if (last) graph_.remember();
}

}  // namespace cosim::rigidbody::world
