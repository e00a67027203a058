#include "tracker/mesh/voronoi_mesh.hpp"

#include "tracker/mesh/assemble.hpp"
#include "tracker/mesh/validate.hpp"

#include <voro++/voro++.hh>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <unordered_map>

namespace cosim::tracker::mesh {
namespace {

// Merges vertices closer than `radius` (cells compute their shared corners separately,
// so copies differ by round-off), with a hash grid of that spacing.
class Welder {
 public:
  explicit Welder(double radius) : radius_(radius) {}

  Index add(const Vec3& x, std::vector<Vec3>& vertices) {
    const std::array<long long, 3> key{cell(x[0]), cell(x[1]), cell(x[2])};
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy)
        for (long long dz = -1; dz <= 1; ++dz) {
          const auto it = buckets_.find(hash({key[0] + dx, key[1] + dy, key[2] + dz}));
          if (it == buckets_.end()) continue;
          for (const Index v : it->second)
            if ((vertices[v] - x).norm() <= radius_) return v;
        }
    vertices.push_back(x);
    const Index v = static_cast<Index>(vertices.size()) - 1;
    buckets_[hash(key)].push_back(v);
    return v;
  }

 private:
  long long cell(double x) const { return static_cast<long long>(std::floor(x / radius_)); }
  // Distinct keys may collide; the distance test above keeps that harmless.
  static std::size_t hash(const std::array<long long, 3>& k) {
    return std::hash<long long>{}(k[0] * 73856093LL ^ k[1] * 19349663LL ^ k[2] * 83492791LL);
  }

  double radius_;
  std::unordered_map<std::size_t, std::vector<Index>> buckets_;
};

}  // namespace

Mesh voronoi_mesh(std::span<const Vec3> points, const VoronoiSpec& spec) {
  const Vec3 size = spec.max - spec.min;
  if (!(size.minCoeff() > 0.0)) throw std::invalid_argument("voronoi mesh: box max must exceed min on every axis");
  if (points.empty()) throw std::invalid_argument("voronoi mesh: no points");
  const int n = static_cast<int>(points.size());
  // About five points per voro++ block, its recommended load.
  const double block = std::cbrt(size.prod() * 5.0 / n);
  std::array<int, 3> blocks{};
  for (int k = 0; k < 3; ++k) blocks[k] = std::max(1, static_cast<int>(size[k] / block));
  voro::container container(spec.min[0], spec.max[0], spec.min[1], spec.max[1], spec.min[2], spec.max[2], blocks[0],
                            blocks[1], blocks[2], spec.periodic[0], spec.periodic[1], spec.periodic[2], 8);
  for (int i = 0; i < n; ++i) {
    const Vec3& p = points[i];
    if ((p.array() < spec.min.array()).any() || (p.array() >= spec.max.array()).any())
      throw std::invalid_argument("voronoi mesh: point " + std::to_string(i) + " is outside the box");
    container.put(i, p[0], p[1], p[2]);
  }

  Polyhedra poly;
  poly.source = "voronoi mesh";
  poly.patches = {"x_min", "x_max", "y_min", "y_max", "z_min", "z_max"};
  for (int k = 0; k < 3; ++k) poly.period[k] = spec.periodic[k] ? size[k] : 0.0;
  Welder welder(1e-10 * size.norm());

  // voro++ visits cells in block order; collect them by particle id.
  struct Cell {
    std::vector<Index> vertex;
    std::vector<int> face_vertices, neighbours;
  };
  std::vector<Cell> cells(n);
  std::vector<bool> done(n, false);
  voro::voronoicell_neighbor vc;
  voro::c_loop_all loop(container);
  if (loop.start()) do {
      const int id = loop.pid();
      if (!container.compute_cell(vc, loop))
        throw std::invalid_argument("voronoi mesh: no cell for point " + std::to_string(id) + " (a coincident point?)");
      double x, y, z;
      loop.pos(x, y, z);
      std::vector<double> xyz;
      vc.vertices(x, y, z, xyz);
      Cell& cell = cells[id];
      for (std::size_t v = 0; v < xyz.size(); v += 3)
        cell.vertex.push_back(welder.add(Vec3(xyz[v], xyz[v + 1], xyz[v + 2]), poly.vertices));
      vc.face_vertices(cell.face_vertices);
      vc.neighbors(cell.neighbours);
      done[id] = true;
    } while (loop.inc());

  for (int i = 0; i < n; ++i) {
    if (!done[i]) throw std::invalid_argument("voronoi mesh: no cell for point " + std::to_string(i));
    const Cell& cell = cells[i];
    std::size_t at = 0;
    for (const int neighbour : cell.neighbours) {
      const int count = cell.face_vertices[at++];
      std::vector<Index> loop_ids;
      for (int k = 0; k < count; ++k) {
        const Index v = cell.vertex[cell.face_vertices[at++]];
        // Welding can merge the ends of a round-off-sized edge.
        if (loop_ids.empty() || loop_ids.back() != v) loop_ids.push_back(v);
      }
      if (loop_ids.size() > 1 && loop_ids.front() == loop_ids.back()) loop_ids.pop_back();
      if (loop_ids.size() < 3) continue;
      // voro++ lists face vertices clockwise seen from outside.
      std::reverse(loop_ids.begin(), loop_ids.end());
      poly.add_face(loop_ids);
      // voro++ names the walls -1 ... -6 in the order of our patches.
      poly.face_neighbour.push_back(neighbour >= 0 ? Index(neighbour) : boundary_code(Index(-1 - neighbour)));
    }
    poly.end_cell();
  }
  Mesh mesh = assemble(std::move(poly));
  require_valid(mesh);
  return mesh;
}

}  // namespace cosim::tracker::mesh
