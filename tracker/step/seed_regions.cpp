#include "tracker/step/seed_regions.hpp"

namespace cosim::tracker::step {

RegionShape::Cover RegionShape::cover(const Eigen::AlignedBox3d& box, const Vec3& centre) const {
  // No primitive's surface passing through the box: every primitive, and so the region, is
  // the same everywhere in it.
  for (const csg::Primitive& p : tree_.primitives())
    if (p.surface_may_meet(box)) return Cover::cut;
  return tree_.contains(centre) ? Cover::inside : Cover::outside;
}

}  // namespace cosim::tracker::step
