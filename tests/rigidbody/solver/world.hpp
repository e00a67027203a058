// A minimal rigid-body world for the solver tests: symplectic Euler around a contact
// solver, with contacts computed analytically from spheres, boxes and planes.
#pragma once

#include <functional>
#include <vector>

#include "rigidbody/solver/dem_solver.hpp"
#include "rigidbody/solver/contact_memory.hpp"
#include "rigidbody/solver/impulse_solver.hpp"
#include "rigidbody/solver/problem.hpp"

namespace cosim::rigidbody::solver::test {

inline const Eigen::Vector3d kGravity{0.0, 0.0, -9.81};

struct Plane {
  std::uint32_t body = 0;  // a fixed body
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  double offset = 0.0;  // normal . x = offset on the plane
};

using Contacts = std::function<std::vector<contact::Manifold>(std::span<const dynamics::BodyState>)>;
using Solver = std::function<SolveReport(const ContactScene&, std::span<CachedContact>)>;

inline Solver impulses(const ImpulseOptions& o) {
  return [o](const ContactScene& s, std::span<CachedContact> m) { return solve_impulses(s, m, o); };
}
inline Solver dem(const DemOptions& o) {
  return [o](const ContactScene& s, std::span<CachedContact> m) -> SolveReport { return solve_dem(s, m, o); };
}

// The impulse solvers by name, for parameterised tests.
struct Preset {
  const char* name;
  ImpulseOptions options;
};
inline const Preset kPgs{"pgs", ImpulseOptions::projected_gauss_seidel()};
inline const Preset kJacobi{"jacobi", ImpulseOptions::projected_jacobi()};
inline const Preset kSi{"si", ImpulseOptions::sequential_impulses()};

struct World {
  std::vector<dynamics::BodyState> states;
  std::vector<dynamics::BodyInertia> inertias;
  Eigen::Vector3d gravity = kGravity;
  Material material;
  ContactMemory memory;               // carried between steps, as the world's contact graph does
  contact::ContactSet contact_set;    // of the last step
  std::vector<CachedContact> values;  // of the last step, one per point

  std::uint32_t add_fixed();
  std::uint32_t add_sphere(double mass, double radius, const Eigen::Vector3d& position);
  std::uint32_t add_box(double mass, const Eigen::Vector3d& half, const Eigen::Vector3d& position,
                        const Eigen::Quaterniond& orientation = Eigen::Quaterniond::Identity());
  // Gravity, contact solve, then positions with the new velocities.
  SolveReport step(double dt, const Contacts& contacts, const Solver& solver);
  double kinetic_energy() const;
};

// Contacts closer than `margin` (speculative) or overlapping.
contact::Manifold sphere_plane(const Plane& plane, std::uint32_t sphere, double radius,
                               std::span<const dynamics::BodyState> states, double margin);
contact::Manifold sphere_sphere(std::uint32_t a, double ra, std::uint32_t b, double rb,
                                std::span<const dynamics::BodyState> states, double margin);
// The (up to 4) lowest corners of the box within `margin`.
contact::Manifold box_plane(const Plane& plane, std::uint32_t box, const Eigen::Vector3d& half,
                            std::span<const dynamics::BodyState> states, double margin);

// Appends m if it has points.
void keep(std::vector<contact::Manifold>& out, const contact::Manifold& m);

}  // namespace cosim::rigidbody::solver::test
