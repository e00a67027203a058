// Non-convex meshes: points sampled on (or spheres inside) the other shape looked up in the
// mesh's distance map, and the mesh's vertices against the other shape's exact distance (or
// its map, for two meshes), so that neither a sharp corner of the other shape nor a vertex
// of the mesh can sink through a face unnoticed. Accurate to the map's error bound.
#include <cmath>
#include <vector>

#include "geometry/queries.hpp"
#include "rigidbody/narrowphase/pairs.hpp"

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

struct Sample {
  Vec3 point;     // body frame of the sampled shape
  double radius;  // of the ball around it that belongs to the shape
};

// The 26 directions to the neighbours of a cube cell: surface samples of smooth shapes.
std::vector<Vec3> directions() {
  std::vector<Vec3> d;
  for (int i = -1; i <= 1; ++i)
    for (int j = -1; j <= 1; ++j)
      for (int k = -1; k <= 1; ++k)
        if (i || j || k) d.push_back(Vec3(i, j, k).normalized());
  return d;
}

std::vector<Sample> samples(const Shape& shape) {
  std::vector<Sample> s;
  const auto add_points = [&](const auto& points) {
    for (const Vec3& p : points) s.push_back({p, 0.0});
  };
  const auto add_support = [&] {
    for (const Vec3& d : directions()) s.push_back({geometry::support(shape, d), 0.0});
  };
  std::visit(
      [&](const auto& x) {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, Sphere>) {
          s.push_back({Vec3::Zero(), x.radius()});
        } else if constexpr (std::is_same_v<T, Capsule>) {
          // Balls along the axis, at most a radius apart, so the union hugs the capsule.
          const int n = 1 + static_cast<int>(std::ceil(x.height() / x.radius()));
          for (int i = 0; i <= n; ++i) s.push_back({Vec3(0.0, 0.0, x.height() * (double(i) / n - 0.5)), x.radius()});
        } else if constexpr (std::is_same_v<T, Box>) {
          for (int i = 0; i < 8; ++i)
            s.push_back({x.half_extents().cwiseProduct(Vec3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1)), 0.0});
        } else if constexpr (std::is_same_v<T, Cylinder>) {
          for (int i = 0; i < 16; ++i) {
            const double phi = 2.0 * M_PI * i / 16;
            for (const double z : {-0.5, 0.5})
              s.push_back({Vec3(x.radius() * std::cos(phi), x.radius() * std::sin(phi), z * x.height()), 0.0});
          }
        } else if constexpr (std::is_same_v<T, ConvexHull> || std::is_same_v<T, TriangleMesh>) {
          add_points(x.vertices());
        } else {
          add_support();  // ellipsoid; half-spaces never get here
        }
      },
      shape);
  return s;
}

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
