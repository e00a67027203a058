#pragma once

#include <Eigen/Core>
#include <vector>

#include "geometry/aabb.hpp"
#include "geometry/detail/closest_on_triangle.hpp"
#include "geometry/triangle.hpp"

namespace cosim::geometry::detail {

// AABB tree over triangles, built once: median split along the widest axis of the
// triangle centroids, at most 4 triangles per leaf, nodes in depth-first order and the
// leaves' corners copied next to each other so a query walks memory forwards.
class TriangleBvh {
 public:
  TriangleBvh(const std::vector<Eigen::Vector3d>& vertices, const std::vector<Triangle>& triangles);

  struct Hit {
    std::uint32_t triangle;  // index into the triangles given to the constructor
    TrianglePoint point;
  };

  // Nearest triangle by branch and bound: children are visited nearest box first and
  // pruned when their box is farther than the best triangle so far. `hint` is a triangle
  // likely to be near (the previous answer in a spatially coherent batch): it only sets the
  // initial bound, so it changes the cost, never the distance.
  Hit closest(const Eigen::Vector3d& p, std::uint32_t hint) const;

 private:
  struct Node {
    Aabb box;
    std::uint32_t first = 0;  // leaf: first slot; inner node: index of the right child
    std::uint32_t count = 0;  // leaf: number of slots; 0 marks an inner node (left child = this + 1)
  };

  std::uint32_t build(std::vector<std::uint32_t>& order, const std::vector<Eigen::Vector3d>& centroids,
                      const std::vector<Aabb>& boxes, std::uint32_t begin, std::uint32_t end);
  TrianglePoint closest_in_slot(const Eigen::Vector3d& p, std::uint32_t slot) const;

  std::vector<Node> nodes_;
  std::vector<std::array<Eigen::Vector3d, 3>> corners_;  // by slot
  std::vector<std::uint32_t> triangle_of_slot_;
  std::vector<std::uint32_t> slot_of_triangle_;
};

}  // namespace cosim::geometry::detail
