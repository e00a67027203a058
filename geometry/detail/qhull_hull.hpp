#pragma once

// Kept free of qhull types and of C++20: its implementation is compiled as C++17 (see
// CMakeLists.txt).
#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace cosim::geometry::detail {

struct QhullFacets {
  std::vector<std::uint32_t> vertices;             // indices of the input points on the hull
  std::vector<std::vector<std::uint32_t>> facets;  // input point indices of each facet, unordered
  std::vector<Eigen::Vector3d> normals;            // outward unit normal of each facet
};

// Convex hull by qhull (Barber, Dobkin & Huhdanpaa 1996) with its default options, which
// merge coplanar facets: a box comes out as 6 quadrilaterals, not 12 triangles. Throws
// std::invalid_argument with qhull's diagnosis for fewer than 4 points or flat input.
QhullFacets qhull_convex_hull(const std::vector<Eigen::Vector3d>& points);

}  // namespace cosim::geometry::detail
