#include "rigidbody/world/world.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "geometry/mass_properties.hpp"

namespace cosim::rigidbody::world {

solver::ImpulseOptions Settings::impulse_options() const {
  solver::ImpulseOptions o = solver == SolverKind::pgs      ? solver::ImpulseOptions::projected_gauss_seidel()
                             : solver == SolverKind::jacobi ? solver::ImpulseOptions::projected_jacobi()
                                                            : solver::ImpulseOptions::sequential_impulses();
  if (iterations > 0) o.max_iterations = iterations;
  o.tolerance = tolerance;
  o.restitution = restitution;
  return o;
}

solver::SoftOptions Settings::soft_options() const {
  solver::SoftOptions o = soft;
  if (iterations > 0) o.iterations = iterations;
  o.tolerance = tolerance;
  return o;
}

World::World(const Settings& settings)
    : settings_(settings), soft_(settings.soft_options()), smallest_radius_(std::numeric_limits<double>::infinity()) {
  if (!(settings.dt > 0.0)) throw std::invalid_argument("world: dt must be positive");
  if (!(settings.contact_margin >= 0.0)) throw std::invalid_argument("world: contact margin must be >= 0");
  if (settings.soft.substeps < 1) throw std::invalid_argument("world: the soft step needs at least one substep");
  const solver::LubricationOptions& l = settings.lubrication;
  if (l.active() && !(l.roughness > 0.0 && l.range > l.roughness))
    throw std::invalid_argument("world: lubrication needs 0 < roughness < range");
}

namespace {

// The radius of curvature the film force takes (solver/lubrication.hpp). A sphere's is
// exact, and so is a capsule's where its cap meets a surface; along its side a capsule is a
// cylinder of that radius, whose film is stronger than a sphere's (a line, not a point),
// so the sphere's law is a lower bound there. Other shapes get their bounding sphere's
// radius, an estimate; a plane's is infinite.
double film_radius(const geometry::Shape& shape) {
  if (const auto* sphere = std::get_if<geometry::Sphere>(&shape)) return sphere->radius();
  if (const auto* capsule = std::get_if<geometry::Capsule>(&shape)) return capsule->radius();
  return geometry::is_bounded(shape) ? geometry::bounding_radius(shape) : std::numeric_limits<double>::infinity();
}

}  // namespace

std::uint32_t World::add(const BodyDesc& body) {
  const bool bounded = geometry::is_bounded(body.shape);
  if (!bounded && !body.fixed)
    throw std::invalid_argument("world: a " + std::string(geometry::name(geometry::kind(body.shape))) +
                                " body must be fixed");
  dynamics::BodyInertia inertia;  // fixed: all zero
  if (!body.fixed) {
    if (!(body.density > 0.0)) throw std::invalid_argument("world: a dynamic body needs a positive density");
    const geometry::MassProperties mp = geometry::mass_properties(body.shape, body.density);
    inertia = dynamics::BodyInertia::of(mp.mass, mp.inertia, body.rotates);
    inertia.density = body.density;
  }
  shapes_.push_back(body.shape);
  if (settings_.lubrication.active()) radii_.push_back(film_radius(body.shape));
  states_.push_back(body.state);
  states_.back().orientation.normalize();
  inertias_.push_back(inertia);
  materials_.push_back(body.material);
  tunnelling_.add(body.name, body.shape);
  if (bounded) smallest_radius_ = std::min(smallest_radius_, geometry::bounding_radius(body.shape));
  // The grid's margin is fixed at construction and the default margin depends on the bodies.
  grid_ = broadphase::HashGrid({.margin = margin()});
  return static_cast<std::uint32_t>(states_.size() - 1);
}

void World::reserve(std::size_t bodies) {
  shapes_.reserve(bodies);
  if (settings_.lubrication.active()) radii_.reserve(bodies);
  states_.reserve(bodies);
  inertias_.reserve(bodies);
  materials_.reserve(bodies);
  tunnelling_.reserve(bodies);
}

// Pairs within the lubrication range must reach the narrow phase whatever the margin.
double World::margin() const {
  const double film = settings_.lubrication.active() ? settings_.lubrication.range : 0.0;
  if (settings_.contact_margin > 0.0 || !std::isfinite(smallest_radius_))
    return std::max(settings_.contact_margin, film);
  return std::max(0.1 * smallest_radius_, film);
}

void World::check_tunnelling(double window, double substep, StepReport& report) {
  const double gain = settings_.body_forces.gravity ? settings_.body_forces.g.norm() * window : 0.0;
  const auto risks = tunnelling_risks(tunnelling_.thinnest(), states_, inertias_, substep, margin(), gain);
  report.tunnelling_bodies = risks.size();
  if (auto warning = tunnelling_.warning(risks, substep)) report.warnings.push_back(std::move(*warning));
}

}  // namespace cosim::rigidbody::world
