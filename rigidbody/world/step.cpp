// The contact part of a substep: broad phase -> contact graph -> narrow phase -> solver,
// and, for the soft step, its relax after the positions moved.
#include <algorithm>

#include "rigidbody/world/world.hpp"

namespace cosim::world {

namespace {

broadphase::Object object_of(std::uint32_t id, const geometry::Shape& shape, const dynamics::BodyState& s,
                             bool fixed) {
  broadphase::Object o{.id = id, .centre = s.position, .fixed = fixed};
  if (const auto* wall = std::get_if<geometry::HalfSpace>(&shape)) {
    // geometry's {n . x <= 0} in the body frame is {R n . x <= R n . p} in the world.
    const Eigen::Vector3d n = s.orientation * wall->normal();
    o.infinite = true;
    o.half_space = broadphase::HalfSpace{n, n.dot(s.position)};
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

solver::SolveReport World::solve(const solver::ContactScene& scene, std::span<solver::CachedContact> memory) {
  switch (settings_.solver) {
    case SolverKind::soft: return soft_.solve(scene, memory);
    case SolverKind::dem: return solver::solve_dem(scene, memory, settings_.dem);
    default: return solver::solve_impulses(scene, memory, settings_.impulse_options());
  }
}

void World::resolve_contacts(double dt, std::span<dynamics::BodyState> states, StepReport& report) {
  ++report.substeps;
  const double margin = this->margin();

  objects_.clear();
  for (std::uint32_t i = 0; i < states.size(); ++i)
    objects_.push_back(object_of(i, shapes_[i], states[i], inertias_[i].is_fixed()));
  grid_.update(objects_);
  grid_.find_pairs(pairs_);
  ++report.broadphase_updates;

  graph_.update(pairs_);
  contact::ContactSet& contacts = graph_.contacts();
  contacts.clear();
  for (const auto& [a, b] : graph_.edges()) {
    contact::Manifold m{.a = a, .b = b};
    const geometry::Pose pa(states[a].position, states[a].orientation);
    const geometry::Pose pb(states[b].position, states[b].orientation);
    narrowphase::collide(shapes_[a], pa, shapes_[b], pb, margin, m, mesh_maps_);
    contacts.add(m);
  }
  report.pairs_tested += graph_.edges().size();
  report.contacts = contacts.points.size();

  pair_materials_.clear();
  for (const contact::PairContacts& p : contacts.pairs) pair_materials_.push_back(combine(materials_[p.a], materials_[p.b]));

  // The solvers split the pairs into contact groups themselves (solver::contact_groups:
  // components linked through dynamic bodies only) and report the worst group.
  mobility_ = solver::mobilities(states, inertias_);
  const solver::ContactScene scene{states, inertias_, mobility_, contacts, pair_materials_, dt};
  // Before the contacts, so the solver sees the velocities the film has left.
  solver::apply_lubrication(scene, radii_, settings_.lubrication);
  const std::span<solver::CachedContact> memory = graph_.recall();
  merge(report, solve(scene, memory));
  // The soft step remembers after its relax, once the positions moved.
  if (settings_.solver != SolverKind::soft) graph_.remember();
}

void World::relax_contacts(std::span<dynamics::BodyState> states, StepReport& report) {
  merge(report, soft_.relax(states, graph_.recalled()));
  graph_.remember();
}

}  // namespace cosim::world
