#pragma once
// Which cell holds a point: a uniform grid of buckets over the cells' bounding boxes.

#include "tracker/mesh/mesh.hpp"

#include <array>
#include <vector>

namespace cosim::tracker::mesh {

// About one bucket per cell over the mesh's bounding box, each listing the cells whose
// (padded) bounding boxes meet it, so a query tests a few cells whatever the mesh size.
// Keeps a reference to the mesh, which must outlive it and keep its geometry.
class PointLocator {
 public:
  explicit PointLocator(const Mesh& mesh);

  // A cell that contains x by its own face planes, or -1 if none does (outside the
  // mesh, or in a gap between the cells of a perturbed mesh). Where cells overlap (on
  // shared faces, or in overlaps of a perturbed mesh) the one listed first.
  Index locate(const Vec3& x) const;

 private:
  std::array<int, 3> bucket_of(const Vec3& x) const;

  const Mesh* mesh_;
  Vec3 lo_, hi_, inverse_width_;
  std::array<int, 3> buckets_{};
  std::vector<Index> bucket_begin_;  // bucket b lists bucket_cells_[begin[b] .. begin[b+1])
  std::vector<Index> bucket_cells_;
};

}  // namespace cosim::tracker::mesh
