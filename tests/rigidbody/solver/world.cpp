#include "tests/rigidbody/solver/world.hpp"

#include <algorithm>
#include <array>
#include <numeric>

namespace cosim::rigidbody::solver::test {

std::uint32_t World::add_fixed() {
  states.emplace_back();
  inertias.push_back(dynamics::BodyInertia::fixed());
  return static_cast<std::uint32_t>(states.size() - 1);
}

std::uint32_t World::add_sphere(double mass, double radius, const Eigen::Vector3d& position) {
  dynamics::BodyState s;
  s.position = position;
  states.push_back(s);
  inertias.push_back(dynamics::BodyInertia::of(mass, 0.4 * mass * radius * radius * Eigen::Matrix3d::Identity()));
  return static_cast<std::uint32_t>(states.size() - 1);
}

std::uint32_t World::add_box(double mass, const Eigen::Vector3d& half, const Eigen::Vector3d& position,
                             const Eigen::Quaterniond& orientation) {
  dynamics::BodyState s;
  s.position = position;
  s.orientation = orientation;
  states.push_back(s);
  const Eigen::Vector3d sq = (2.0 * half).cwiseAbs2();
  const Eigen::Vector3d diag = mass / 12.0 * Eigen::Vector3d(sq.y() + sq.z(), sq.x() + sq.z(), sq.x() + sq.y());
  inertias.push_back(dynamics::BodyInertia::of(mass, diag.asDiagonal()));
  return static_cast<std::uint32_t>(states.size() - 1);
}

SolveReport World::step(double dt, const Contacts& contacts, const Solver& solver) {
  for (std::size_t i = 0; i < states.size(); ++i)
    if (!inertias[i].is_fixed()) states[i].velocity += dt * gravity;
  contact_set.clear();
  // Sorted by pair, as the world's contact graph hands them to the solver.
  std::vector<contact::Manifold> manifolds = contacts(states);
  std::sort(manifolds.begin(), manifolds.end(), [](const contact::Manifold& x, const contact::Manifold& y) {
    return std::pair(x.a, x.b) < std::pair(y.a, y.b);
  });
  for (const contact::Manifold& m : manifolds) contact_set.add(m);
  const std::vector<Material> materials(contact_set.pairs.size(), material);
  memory.recall(contact_set, values);
  const std::vector<Mobility> mobility = mobilities(states, inertias);
  const SolveReport report = solver({states, inertias, mobility, contact_set, materials, dt}, values);
  memory.remember(contact_set, values);
  for (auto& s : states) {
    s.position += dt * s.velocity;
    const Eigen::Quaterniond spin(0.0, s.angular_velocity.x(), s.angular_velocity.y(), s.angular_velocity.z());
    s.orientation.coeffs() += 0.5 * dt * (spin * s.orientation).coeffs();
    s.orientation.normalize();
  }
  return report;
}

double World::kinetic_energy() const {
  double e = 0.0;
  for (std::size_t i = 0; i < states.size(); ++i) {
    if (inertias[i].is_fixed()) continue;
    const auto& s = states[i];
    const Eigen::Matrix3d r = s.orientation.toRotationMatrix();
    const Eigen::Matrix3d inertia = r * inertias[i].inertia_body() * r.transpose();
    e += 0.5 * s.velocity.squaredNorm() / inertias[i].inverse_mass +
         0.5 * s.angular_velocity.dot(inertia * s.angular_velocity);
  }
  return e;
}

contact::Manifold sphere_plane(const Plane& plane, std::uint32_t sphere, double radius,
                               std::span<const dynamics::BodyState> states, double margin) {
  contact::Manifold m{.a = plane.body, .b = sphere};
  const Eigen::Vector3d& c = states[sphere].position;
  const double d = plane.normal.dot(c) - plane.offset - radius;
  if (d < margin) m.add({c - plane.normal * (radius + 0.5 * d), plane.normal, d, 0});
  return m;
}

contact::Manifold sphere_sphere(std::uint32_t a, double ra, std::uint32_t b, double rb,
                                std::span<const dynamics::BodyState> states, double margin) {
  contact::Manifold m{.a = a, .b = b};
  const Eigen::Vector3d axis = states[b].position - states[a].position;
  const double d = axis.norm() - ra - rb;
  const Eigen::Vector3d n = axis.normalized();
  if (d < margin) m.add({states[a].position + n * (ra + 0.5 * d), n, d, 0});
  return m;
}

contact::Manifold box_plane(const Plane& plane, std::uint32_t box, const Eigen::Vector3d& half,
                            std::span<const dynamics::BodyState> states, double margin) {
  const auto& s = states[box];
  std::array<Eigen::Vector3d, 8> corners;
  std::array<double, 8> gaps;
  for (std::uint32_t i = 0; i < 8; ++i) {
    const Eigen::Vector3d sign(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
    corners[i] = s.position + s.orientation * half.cwiseProduct(sign);
    gaps[i] = plane.normal.dot(corners[i]) - plane.offset;
  }
  std::array<std::uint32_t, 8> order;
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](auto i, auto j) { return gaps[i] < gaps[j]; });
  contact::Manifold m{.a = plane.body, .b = box};
  for (std::size_t k = 0; k < contact::Manifold::kMaxPoints; ++k) {
    const std::uint32_t i = order[k];
    if (gaps[i] < margin) m.add({corners[i] - 0.5 * gaps[i] * plane.normal, plane.normal, gaps[i], i});
  }
  return m;
}

void keep(std::vector<contact::Manifold>& out, const contact::Manifold& m) {
  if (m.count > 0) out.push_back(m);
}

}  // namespace cosim::rigidbody::solver::test
