#include "geometry/inner_spheres.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace cosim::geometry {
namespace {

// Calls f(index) for the grid nodes inside the ball.
template <class F>
void for_each_node_in_ball(const GridSpec& g, const InnerSphere& s, F f) {
  std::array<int, 3> lo{}, hi{};
  for (int a = 0; a < 3; ++a) {
    lo[a] = std::max(0, static_cast<int>(std::ceil((s.center[a] - s.radius - g.origin[a]) / g.spacing)));
    hi[a] = std::min(g.count[a] - 1, static_cast<int>(std::floor((s.center[a] + s.radius - g.origin[a]) / g.spacing)));
  }
  for (int k = lo[2]; k <= hi[2]; ++k)
    for (int j = lo[1]; j <= hi[1]; ++j)
      for (int i = lo[0]; i <= hi[0]; ++i)
        if ((g.node(i, j, k) - s.center).squaredNorm() <= s.radius * s.radius) f(g.index(i, j, k));
}

}  // namespace

InnerSphereSet inner_spheres(const DistanceMap& map, double fraction) {
  if (!(fraction > 0.0 && fraction <= 1.0))
    throw std::invalid_argument("inner spheres: fraction must be in (0, 1], got " + std::to_string(fraction));
  const GridSpec& nodes = map.grid();
  const std::span<const double> values = map.values();

  // Covered volume = covered cell centres x h^3 (a midpoint rule), against the exact volume.
  // Not counted on the nodes: every candidate is centred on one, so a sphere much thinner
  // than a cell would be credited with a whole cell.
  const double h = nodes.spacing;
  const GridSpec cells{nodes.origin + Eigen::Vector3d::Constant(0.5 * h),
                       h,
                       {nodes.count[0] - 1, nodes.count[1] - 1, nodes.count[2] - 1}};
  const double cell_volume = h * h * h;
  const double target = fraction * map.shape_volume();

  // A sphere on a node thinner than half a cell diagonal holds no cell centre: useless.
  std::vector<std::size_t> candidates;
  for (std::size_t n = 0; n < values.size(); ++n)
    if (-values[n] >= 0.5 * std::sqrt(3.0) * h) candidates.push_back(n);
  if (candidates.empty())
    throw std::invalid_argument("inner spheres: no node is a cell deep inside; use a finer spacing");
  std::stable_sort(candidates.begin(), candidates.end(),
                   [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });

  std::vector<std::uint8_t> covered(cells.size(), 0);
  // depth[n]: how far node n lies inside the deepest taken sphere (-inf: in none).
  std::vector<double> depth(nodes.size(), -std::numeric_limits<double>::infinity());
  std::size_t covered_cells = 0;
  InnerSphereSet set;
  // First pass: only candidates centred outside every taken sphere, which keeps the set
  // sparse (no pile of equal spheres sliding along a box). Second pass, if still short:
  // any candidate not contained in a taken sphere that covers a new cell centre.
  for (const bool sparse : {true, false}) {
    for (std::size_t n : candidates) {
      if (static_cast<double>(covered_cells) * cell_volume >= target) break;
      const InnerSphere s{nodes.node(n), -values[n]};
      if (sparse ? depth[n] >= 0.0 : s.radius <= depth[n]) continue;
      std::size_t added = 0;
      for_each_node_in_ball(cells, s, [&](std::size_t c) {
        added += !covered[c];
        covered[c] = 1;
      });
      if (added == 0) continue;
      covered_cells += added;
      set.spheres.push_back(s);
      for_each_node_in_ball(nodes, s, [&](std::size_t m) {
        depth[m] = std::max(depth[m], s.radius - (nodes.node(m) - s.center).norm());
      });
    }
  }
  set.covered_fraction = static_cast<double>(covered_cells) * cell_volume / map.shape_volume();
  return set;
}

}  // namespace cosim::geometry
