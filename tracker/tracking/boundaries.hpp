#pragma once
// What happens at boundary faces, by patch: reflections, re-emission, removal.

#include "tracker/constants.hpp"
#include "tracker/tracking/particle.hpp"

#include <vector>

namespace cosim::tracker {


enum class BoundaryKind {
  specular,  // mirror the normal velocity
  diffuse,   // re-emit from a Maxwellian at the wall temperature
  maxwell,   // diffuse with probability `accommodation`, specular otherwise
  open,      // inflow or outflow: a particle that reaches it leaves the domain
  periodic,  // linked by the mesh (Face::shift); its faces are never reached as walls
};

struct BoundaryCondition {
  BoundaryKind kind = BoundaryKind::specular;
  double temperature = 0.0;    // K (diffuse, maxwell)
  double accommodation = 1.0;  // maxwell: the diffuse fraction
};

// Diffuse and Maxwell walls draw new velocities: they need a temperature and a mass.
inline bool re_emits(const BoundaryCondition& wall) {
  return wall.kind == BoundaryKind::diffuse || wall.kind == BoundaryKind::maxwell;
}

struct Boundaries {
  std::vector<BoundaryCondition> patches;  // by index into Mesh::patches
  double mass = 0.0;                       // particle mass in kg, for re-emission
};

// The velocity after a wall hit (n the wall's unit normal, pointing into the domain), or
// false if the particle leaves through an open patch.
bool hit_wall(const Boundaries& boundaries, Index patch, const Vec3& n, Vec3& v, Random& random);
// The same for a wall with this condition (CSG obstacles have their own).
bool hit_wall(const BoundaryCondition& wall, double mass, const Vec3& n, Vec3& v, Random& random);

Vec3 specular(const Vec3& v, const Vec3& n);
// Maxwellian re-emission: the normal component from the flux-weighted distribution
// (sigma sqrt(-2 ln U), mean sigma sqrt(pi / 2)), the tangential ones Gaussian;
// sigma^2 = k_B T / m.
Vec3 diffuse(const Vec3& n, double temperature, double mass, Random& random);

}  // namespace cosim::tracker
