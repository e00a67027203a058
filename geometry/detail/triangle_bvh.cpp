#include "geometry/detail/triangle_bvh.hpp"

#include <algorithm>
#include <numeric>
#include <utility>

namespace cosim::geometry::detail {
namespace {

constexpr std::uint32_t max_leaf_size = 4;
// Median splits halve the range, so the depth is at most log2(2^32) plus a margin.
constexpr int max_depth = 64;

}  // namespace

TriangleBvh::TriangleBvh(const std::vector<Eigen::Vector3d>& vertices, const std::vector<Triangle>& triangles) {
  const auto n = static_cast<std::uint32_t>(triangles.size());
  std::vector<Eigen::Vector3d> centroids(n);
  std::vector<Aabb> boxes(n);
  for (std::uint32_t t = 0; t < n; ++t) {
    for (std::uint32_t v : triangles[t]) boxes[t].extend(vertices[v]);
    centroids[t] = (vertices[triangles[t][0]] + vertices[triangles[t][1]] + vertices[triangles[t][2]]) / 3.0;
  }
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  nodes_.reserve(2 * n / max_leaf_size + 1);
  build(order, centroids, boxes, 0, n);

  triangle_of_slot_ = std::move(order);
  slot_of_triangle_.resize(n);
  corners_.resize(n);
  for (std::uint32_t s = 0; s < n; ++s) {
    const Triangle& t = triangles[triangle_of_slot_[s]];
    slot_of_triangle_[triangle_of_slot_[s]] = s;
    corners_[s] = {vertices[t[0]], vertices[t[1]], vertices[t[2]]};
  }
}

std::uint32_t TriangleBvh::build(std::vector<std::uint32_t>& order, const std::vector<Eigen::Vector3d>& centroids,
                                 const std::vector<Aabb>& boxes, std::uint32_t begin, std::uint32_t end) {
  const auto index = static_cast<std::uint32_t>(nodes_.size());
  nodes_.emplace_back();
  Aabb box, centre_box;
  for (std::uint32_t i = begin; i < end; ++i) {
    box.extend(boxes[order[i]].min);
    box.extend(boxes[order[i]].max);
    centre_box.extend(centroids[order[i]]);
  }
  nodes_[index].box = box;
  if (end - begin <= max_leaf_size) {
    nodes_[index].first = begin;
    nodes_[index].count = end - begin;
    return index;
  }
  Eigen::Index axis = 0;
  (centre_box.max - centre_box.min).maxCoeff(&axis);
  const std::uint32_t mid = begin + (end - begin) / 2;
  std::nth_element(order.begin() + begin, order.begin() + mid, order.begin() + end,
                   [&](std::uint32_t a, std::uint32_t b) { return centroids[a][axis] < centroids[b][axis]; });
  build(order, centroids, boxes, begin, mid);
  const std::uint32_t right = build(order, centroids, boxes, mid, end);
  nodes_[index].first = right;
  return index;
}

TrianglePoint TriangleBvh::closest_in_slot(const Eigen::Vector3d& p, std::uint32_t slot) const {
  const auto& c = corners_[slot];
  return closest_on_triangle(p, c[0], c[1], c[2]);
}

TriangleBvh::Hit TriangleBvh::closest(const Eigen::Vector3d& p, std::uint32_t hint) const {
  std::uint32_t best_slot = slot_of_triangle_[hint];
  TrianglePoint best = closest_in_slot(p, best_slot);

  std::pair<std::uint32_t, double> stack[max_depth];
  int top = 0;
  stack[top++] = {0u, nodes_[0].box.squared_distance(p)};
  while (top > 0 && best.squared_distance > 0.0) {
    const auto [index, box_distance] = stack[--top];
    if (box_distance >= best.squared_distance) continue;
    const Node& node = nodes_[index];
    if (node.count > 0) {
      for (std::uint32_t s = node.first; s < node.first + node.count; ++s) {
        const TrianglePoint candidate = closest_in_slot(p, s);
        if (candidate.squared_distance < best.squared_distance) {
          best = candidate;
          best_slot = s;
        }
      }
      continue;
    }
    std::pair<std::uint32_t, double> near{index + 1, nodes_[index + 1].box.squared_distance(p)};
    std::pair<std::uint32_t, double> far{node.first, nodes_[node.first].box.squared_distance(p)};
    if (far.second < near.second) std::swap(near, far);
    if (far.second < best.squared_distance) stack[top++] = far;
    if (near.second < best.squared_distance) stack[top++] = near;
  }
  return {triangle_of_slot_[best_slot], best};
}

}  // namespace cosim::geometry::detail
