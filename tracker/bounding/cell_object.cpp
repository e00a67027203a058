#include "tracker/bounding/cell_object.hpp"

#include "tracker/mesh/geometry.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace cosim::tracker::bounding {
namespace {

Eigen::AlignedBox3d enlarged_box(const mesh::Mesh& mesh, Index cell, double margin) {
  const Eigen::AlignedBox3d box = mesh::cell_box(mesh, cell);
  const Vec3 grow = Vec3::Constant(margin * box.diagonal().norm());
  return {box.min() - grow, box.max() + grow};
}

// Per cell, the object's primitives whose surface may meet the cell's box: O(cells x
// primitives) tests, most of them rejected by the primitive's bounding box.
std::vector<std::vector<int>> touching(const mesh::Mesh& mesh, const csg::Tree& object, double margin) {
  std::vector<std::vector<int>> near(static_cast<std::size_t>(mesh.cell_count()));
  const auto& primitives = object.primitives();
  std::vector<Eigen::AlignedBox3d> bounds;
  for (const csg::Primitive& p : primitives) bounds.push_back(p.bounds());
  for (Index c = 0; c < mesh.cell_count(); ++c) {
    const Eigen::AlignedBox3d box = enlarged_box(mesh, c, margin);
    for (std::size_t p = 0; p < primitives.size(); ++p)
      if (bounds[p].intersects(box) && primitives[p].surface_may_meet(box))
        near[static_cast<std::size_t>(c)].push_back(static_cast<int>(p));
  }
  return near;
}

// A cell's own primitives and its face neighbours', ascending. Not across periodic faces:
// the primitives there are the images on the other side, which the tracking evaluates
// directly on crossing (Obstacles::transfer).
std::vector<int> with_ring(const mesh::Mesh& mesh, const std::vector<std::vector<int>>& near, Index cell) {
  std::vector<int> all = near[static_cast<std::size_t>(cell)];
  for (Index f = mesh.cell_faces[cell]; f < mesh.cell_faces[cell + 1]; ++f) {
    const mesh::Face& face = mesh.faces[static_cast<std::size_t>(f)];
    const Index n = face.neighbour;
    if (n >= 0 && face.shift == 0)
      all.insert(all.end(), near[static_cast<std::size_t>(n)].begin(), near[static_cast<std::size_t>(n)].end());
  }
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  return all;
}

}  // namespace

CellObject::CellObject(const mesh::Mesh& mesh, const csg::Tree& object, double margin) {
  const std::vector<std::vector<int>> near = touching(mesh, object, margin);
  trees_.push_back(csg::Tree::fixed(false));
  trees_.push_back(csg::Tree::fixed(true));
  first_.push_back(0);
  for (Index c = 0; c < mesh.cell_count(); ++c) {
    const std::vector<int> kept = with_ring(mesh, near, c);
    if (kept.size() > static_cast<std::size_t>(csg::max_primitives))
      throw std::invalid_argument(mesh.source + ": cell " + std::to_string(mesh.global_cell(c)) + " needs " +
                                  std::to_string(kept.size()) + " primitives of a CSG object, a logical state holds " +
                                  std::to_string(csg::max_primitives) + ": refine the mesh there");
    // Left-out primitives are constant in the cell: their value at the centroid is theirs.
    const Vec3& centre = mesh.centroid[static_cast<std::size_t>(c)];
    csg::Tree tree =
        object.pruned(kept, [&](int p) { return object.primitives()[static_cast<std::size_t>(p)].contains(centre); });
    if (kept.empty()) {
      tree_of_.push_back(tree.evaluate(0) ? 1 : 0);
    } else {
      tree_of_.push_back(static_cast<std::int32_t>(trees_.size()));
      trees_.push_back(std::move(tree));
    }
    primitives_.insert(primitives_.end(), kept.begin(), kept.end());
    first_.push_back(static_cast<Index>(primitives_.size()));
  }
}

std::span<const int> CellObject::primitives(Index cell) const {
  const auto c = static_cast<std::size_t>(cell);
  return {primitives_.data() + first_[c], static_cast<std::size_t>(first_[c + 1] - first_[c])};
}

csg::State CellObject::classify(Index cell, const Vec3& x) const { return tree(cell).classify(x); }

csg::State CellObject::transfer(csg::State state, Index from, Index to, const Vec3& x) const {
  return carry(primitives(from), state, to, x);
}

csg::State CellObject::carry(std::span<const int> old, csg::State state, Index to, const Vec3& x) const {
  const std::span<const int> now = primitives(to);
  const auto& local = tree(to).primitives();
  csg::State out = 0;
  std::size_t i = 0;
  for (std::size_t j = 0; j < now.size(); ++j) {
    while (i < old.size() && old[i] < now[j]) ++i;
    const bool inside =
        i < old.size() && old[i] == now[j] ? csg::test(state, static_cast<int>(i)) : local[j].contains(x);
    if (inside) out |= csg::bit(static_cast<int>(j));
  }
  return out;
}

CellObjectStats CellObject::stats() const {
  CellObjectStats s;
  const auto cells = static_cast<Index>(tree_of_.size());
  for (Index c = 0; c < cells; ++c) {
    const int n = static_cast<int>(primitives(c).size());
    s.mean_primitives += n;
    s.max_primitives = std::max(s.max_primitives, n);
    if (tree(c).constant()) ++s.constant_cells;
  }
  if (cells > 0) s.mean_primitives /= cells;
  return s;
}

}  // namespace cosim::tracker::bounding
