// Regions of the initial gas (Seeding::regions), as SPARTA's `create_particles ... region`:
// each region fills its part of the free space at its own number density, temperature and
// drift; where regions overlap their gases add up, as two create_particles commands do.
// How a cell is filled: seed_particles.hpp.
#pragma once

#include <Eigen/Geometry>

#include "tracker/csg/expression.hpp"
#include "tracker/csg/tree.hpp"
#include "tracker/mesh/mesh.hpp"

namespace cosim::tracker::step {

struct SeedRegion {
  csg::Expression shape;
  double number_density = 0.0;   // real molecules per m^3; Seeding::weight of them per simulator
  double temperature = 0.0;      // K: Maxwellian about the velocity (0: all at the velocity)
  Vec3 velocity = Vec3::Zero();  // m/s, the drift
};

// A region's shape against the cells: whether a cell lies wholly outside it (no draws),
// wholly inside (every draw kept) or is cut by its surface (each draw tested).
class RegionShape {
 public:
  enum class Cover { outside, inside, cut };

  explicit RegionShape(const csg::Expression& shape) : tree_(shape) {}
  // `box` bounds the cell, `centre` lies in it.
  Cover cover(const Eigen::AlignedBox3d& box, const Vec3& centre) const;
  // Round-off decides within about 1e-16 of the surface.
  bool contains(const Vec3& x) const { return tree_.contains(x); }

 private:
  csg::Tree tree_;
};

}  // namespace cosim::tracker::step
