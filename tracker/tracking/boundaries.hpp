#pragma once
// What happens at boundary faces, by patch: reflections, re-emission, removal.

#include "tracker/constants.hpp"
#include "tracker/tracking/particle.hpp"

#include <vector>

namespace cosim::tracker::tracking {

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
  // m/s (diffuse, maxwell): the wall slides along itself at this velocity's tangential part,
  // the mean of the Maxwellian it re-emits from. The normal part is dropped: a mesh patch
  // does not move (CSG walls move by Obstacles::set_pose). A mirror in the frame of a wall
  // sliding along itself is the plain mirror, so specular and open walls refuse a velocity
  // (it would silently do nothing), and Maxwell's specular fraction is the plain mirror.
  Vec3 velocity = Vec3::Zero();
};

// Diffuse and Maxwell walls draw new velocities: they need a temperature and a mass.
inline bool re_emits(const BoundaryCondition& wall) {
  return wall.kind == BoundaryKind::diffuse || wall.kind == BoundaryKind::maxwell;
}
// A velocity on a wall that cannot use it (see BoundaryCondition::velocity).
inline bool refuses_velocity(const BoundaryCondition& wall) { return !re_emits(wall) && wall.velocity != Vec3::Zero(); }

// What the particles gave a surface (a mesh patch; ObstacleTally adds what only objects
// have), summed over hits, per unit particle mass: times the mass and the simulator weight
// over the sampled time, `impulse` is the force on the surface and `energy` the heat it
// takes; over its area, the stress (shear from the tangential part) and the heat flux.
struct SurfaceTally {
  long long hits = 0;           // reflections, absorptions included
  long long absorbed = 0;       // removed at an open surface
  Vec3 impulse = Vec3::Zero();  // sum of v_before - v_after (after = 0 when absorbed)
  double energy = 0.0;          // sum of (|v_before|^2 - |v_after|^2) / 2
  void add(const SurfaceTally& other);
  void exchange(const Vec3& before, const Vec3& after);
};

struct Boundaries {
  std::vector<BoundaryCondition> patches;  // by index into Mesh::patches
  double mass = 0.0;                       // particle mass in kg, for re-emission
};

// The velocity after a wall hit (n the wall's unit normal, pointing into the domain), or
// false if the particle leaves through an open patch. Diffuse re-emission adds the wall
// velocity's part tangential to n.
bool hit_wall(const Boundaries& boundaries, Index patch, const Vec3& n, Vec3& v, Random& random);
// The same for a wall with this condition (CSG obstacles have their own).
bool hit_wall(const BoundaryCondition& wall, double mass, const Vec3& n, Vec3& v, Random& random);

Vec3 specular(const Vec3& v, const Vec3& n);
// Maxwellian re-emission: the normal component from the flux-weighted distribution
// (sigma sqrt(-2 ln U), mean sigma sqrt(pi / 2)), the tangential ones Gaussian;
// sigma^2 = k_B T / m.
Vec3 diffuse(const Vec3& n, double temperature, double mass, Random& random);

}  // namespace cosim::tracker::tracking
