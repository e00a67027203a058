// The contact part of a substep: broad phase -> contact graph -> narrow phase -> solver.
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

}  // namespace

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
  for (ContactGraph::Edge& edge : graph_.edges()) {
    contact::Manifold& m = edge.manifold;
    m.count = 0;
    const geometry::Pose pa(states[m.a].position, states[m.a].orientation);
    const geometry::Pose pb(states[m.b].position, states[m.b].orientation);
    narrowphase::collide(shapes_[m.a], pa, shapes_[m.b], pb, margin, m, mesh_maps_);
  }
  report.pairs_tested += graph_.edges().size();

  const std::span<const contact::Manifold> manifolds = graph_.touching();
  pair_materials_.clear();
  for (const contact::Manifold& m : manifolds) pair_materials_.push_back(combine(materials_[m.a], materials_[m.b]));
  report.contacts = 0;
  for (const contact::Manifold& m : manifolds) report.contacts += m.count;

  // The solvers split the manifolds into contact groups themselves (solver::contact_groups:
  // components linked through dynamic bodies only) and report the worst group.
  const solver::ContactScene scene{states, inertias_, manifolds, pair_materials_, dt};
  const solver::SolveReport solved =
      settings_.solver == SolverKind::dem ? solver::solve_dem(scene, graph_.impulses(), settings_.dem)
                                          : solver::solve_impulses(scene, graph_.impulses(), settings_.impulse_options());
  report.solver_iterations = std::max(report.solver_iterations, solved.iterations);
  report.residual = std::max(report.residual, solved.residual);
  report.converged = report.converged && solved.converged;
}

}  // namespace cosim::world
