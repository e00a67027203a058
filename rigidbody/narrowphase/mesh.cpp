// Non-convex meshes: points sampled on (or spheres inside) the other shape looked up in the
// mesh's distance map, and the mesh's vertices against the other shape's exact distance (or
// its map, for two meshes), so that neither a sharp corner of the other shape nor a vertex
// of the mesh can sink through a face unnoticed. Accurate to the map's error bound.
#include <cmath>
#include <vector>

#include "geometry/queries.hpp"
#include "rigidbody/narrowphase/pairs.hpp"
#include "rigidbody/narrowphase/shape_samples.hpp"

namespace cosim::rigidbody::narrowphase {

const geometry::DistanceMap& MeshMaps::get(const geometry::TriangleMesh& mesh) {
  const void* key = &mesh.vertices();
  std::lock_guard lock(mutex_);
  auto it = entries_.find(key);
  if (it == entries_.end()) {
    // The margin keeps the centres of inner spheres and samples near the surface on the grid.
    const double radius = mesh.bounding_radius();
    auto map =
        std::make_unique<const geometry::DistanceMap>(geometry::Shape(mesh), radius / resolution_, 0.25 * radius);
    it = entries_.emplace(key, Entry{mesh, std::move(map)}).first;
  }
  return *it->second.map;
}

namespace detail {
namespace {

// The samples of b against the map of a.
void samples_in_map(const geometry::DistanceMap& map, const Pose& pa, const std::vector<Sample>& samples,
                    const Pose& pb, std::uint32_t tag, Candidates& out) {
  std::uint32_t feature = tag;
  for (const Sample& s : samples) {
    const auto c = map.closest(pa.to_body(pb.to_world(s.point)));
    out.add(pa.to_world(c.point), pa.direction_to_world(c.normal), c.distance - s.radius, feature++);
  }
}

}  // namespace

void mesh_pair(const TriangleMesh& a, const Pose& pa, const Shape& b, const Pose& pb, MeshMaps& maps, Candidates& out) {
  samples_in_map(maps.get(a), pa, samples(b), pb, 0, out);
  // a's vertices against b, with normals turned to point from a to b.
  std::vector<Sample> vertices;
  for (const Vec3& v : a.vertices()) vertices.push_back({v, 0.0});
  Candidates reverse;
  reverse.margin = out.margin;
  if (const auto* mesh = std::get_if<TriangleMesh>(&b)) {
    samples_in_map(maps.get(*mesh), pb, vertices, pa, 0x10000u, reverse);
  } else {
    const double reach = geometry::bounding_radius(b) + out.margin;
    std::uint32_t feature = 0x10000u;
    for (const Sample& v : vertices) {
      const Vec3 x = pa.to_world(v.point);
      if ((x - pb.position()).norm() <= reach) {
        const auto c = geometry::closest_point(b, pb, x);
        reverse.add(c.point, c.normal, c.distance, feature);
      }
      ++feature;
    }
  }
  for (auto p : reverse.points) {
    p.normal = -p.normal;
    out.points.push_back(p);
  }
}

}  // namespace detail
}  // namespace cosim::rigidbody::narrowphase
