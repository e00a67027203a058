#include "tracker/tracking/inflow.hpp"

#include "tracker/tracking/handover.hpp"

#include "tracker/mesh/geometry.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace cosim::tracker::tracking {
namespace {

constexpr double sqrt_pi = 1.0 / std::numbers::inv_sqrtpi;

// The cumulative inflow distribution, unnormalised: the integral of t e^(-(t - s)^2) from 0
// to x.
double cumulative(double s, double x) {
  return 0.5 * (std::exp(-s * s) - std::exp(-(x - s) * (x - s))) + 0.5 * s * sqrt_pi * (std::erf(x - s) + std::erf(s));
}

}  // namespace

double flux_factor(double s) { return (std::exp(-s * s) + sqrt_pi * s * (1.0 + std::erf(s))) / (2.0 * sqrt_pi); }

double inflow_normal_speed(double s, double u) {
  // The total is sqrt(pi) * flux_factor(s); solve cumulative(x) = u * total by Newton's
  // method kept inside a bracket that bisection shrinks when a step leaves it.
  const double target = u * sqrt_pi * flux_factor(s);
  double lo = 0.0, hi = std::max(0.0, s) + 8.0;
  double x = std::max(0.5, s);
  for (int i = 0; i < 100; ++i) {
    const double f = cumulative(s, x) - target;
    if (f > 0.0)
      hi = x;
    else
      lo = x;
    const double density = x * std::exp(-(x - s) * (x - s));
    double next = density > 0.0 ? x - f / density : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - x) <= 1e-14 * std::max(1.0, x)) return next;
    x = next;
  }
  return x;
}

Inflow::Inflow(const mesh::Mesh& mesh, const std::vector<Index>& patches, const Stream& stream)
    : mesh_(mesh), patches_(patches), stream_(stream) {
  if (!(stream.number_density > 0.0 && stream.temperature > 0.0 && stream.mass > 0.0 && stream.weight > 0.0))
    throw std::invalid_argument("inflow: number density, temperature, mass and weight must be positive");
  most_probable_ = std::sqrt(2.0 * boltzmann * stream.temperature / stream.mass);
  for (const Index patch : patches) {
    const std::size_t before = entries_.size();
    for (Index f = 0; f < mesh.face_count(); ++f) {
      if (mesh.faces[f].neighbour != mesh::boundary_code(patch) || mesh.cell_of_face(f) >= mesh.own_cells()) continue;
      const double area = mesh::area_vector(mesh, f).norm();
      const double s = stream.velocity.dot(mesh.faces[f].normal) / most_probable_;
      const double rate = stream.number_density / stream.weight * most_probable_ * flux_factor(s) * area;
      const Vec3 t1 = mesh.faces[f].normal.unitOrthogonal();
      entries_.push_back({f, mesh.cell_of_face(f), rate, s, area, t1, mesh.faces[f].normal.cross(t1)});
      rate_ += rate;
    }
    if (entries_.size() == before && !mesh.partial)
      throw std::invalid_argument(mesh.source + ": inflow patch " + std::to_string(patch) + " has no boundary faces");
  }
}

Vec3 Inflow::point_on(const Entry& entry, Random& random) const {
  // A triangle of the fan from the first vertex by area, then a uniform point in it.
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const Index n = mesh_.vertex_count(entry.face);
  const Vec3& a = mesh_.face_vertex(entry.face, 0);
  double pick = uniform(random) * entry.area;
  Index k = 1;
  for (; k + 2 < n; ++k) {
    const double triangle =
        0.5 * (mesh_.face_vertex(entry.face, k) - a).cross(mesh_.face_vertex(entry.face, k + 1) - a).norm();
    if (pick < triangle) break;
    pick -= triangle;
  }
  double r1 = uniform(random), r2 = uniform(random);
  if (r1 + r2 > 1.0) {
    r1 = 1.0 - r1;
    r2 = 1.0 - r2;
  }
  return a + r1 * (mesh_.face_vertex(entry.face, k) - a) + r2 * (mesh_.face_vertex(entry.face, k + 1) - a);
}

Vec3 Inflow::velocity(const Entry& entry, Random& random) const {
  const Vec3& n = mesh_.faces[entry.face].normal;  // into the domain
  const Vec3 &t1 = entry.t1, &t2 = entry.t2;
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::normal_distribution<double> gauss(0.0, most_probable_ / std::numbers::sqrt2);
  const double normal = most_probable_ * inflow_normal_speed(entry.speed_ratio, uniform(random));
  return normal * n + (stream_.velocity.dot(t1) + gauss(random)) * t1 + (stream_.velocity.dot(t2) + gauss(random)) * t2;
}

long Inflow::inject(const MoveContext& step, double dt, Swarm& swarm) const {
  const Obstacles& obstacles = step.obstacles;
  Random& random = step.random;
  if (step.domain.mesh.ghosts > 0 && step.away == nullptr)
    throw std::invalid_argument("Inflow::inject: a part of a mesh needs a handover for the moves that leave it");
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<csg::State> states(static_cast<std::size_t>(obstacles.count()));
  long entered = 0;
  for (const Entry& entry : entries_) {
    const auto count = static_cast<long>(std::floor(entry.rate * dt + uniform(random)));
    const Index cell = entry.cell;
    for (long i = 0; i < count; ++i) {
      Particle p{point_on(entry, random), velocity(entry, random), cell};
      obstacles.classify(cell, p.x, states);
      if (obstacles.inside_wall(cell, states)) continue;  // the face is covered by a wall there
      const MoveResult result = move(step, p, states, uniform(random) * dt);
      ++entered;
      if (step.away == nullptr ? !result.removed : step.away->keeps(result, p, states, step.domain.mesh))
        swarm.add(p, states);
    }
  }
  return entered;
}

}  // namespace cosim::tracker::tracking
