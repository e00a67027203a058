#include "geometry/convex_hull.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "geometry/detail/mesh_core.hpp"
#include "geometry/detail/polyhedral_mass.hpp"
#include "geometry/detail/qhull_hull.hpp"

namespace cosim::geometry {

struct ConvexHull::Data {
  std::vector<std::vector<std::uint32_t>> faces;
  std::vector<Plane> planes;
  Eigen::Vector3d com_shift;
  double volume;
  Eigen::Matrix3d unit_inertia;
  detail::MeshCore core;
};

namespace {

// qhull lists a merged facet's vertices in no particular order: sort them by angle about
// the facet centroid, counter-clockwise about the outward normal.
void order_loop(std::vector<std::uint32_t>& loop, const std::vector<Eigen::Vector3d>& v,
                const Eigen::Vector3d& normal) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (std::uint32_t i : loop) c += v[i];
  c /= static_cast<double>(loop.size());
  const Eigen::Vector3d u = (v[loop.front()] - c).normalized();
  const Eigen::Vector3d w = normal.cross(u);
  std::vector<std::pair<double, std::uint32_t>> by_angle;
  for (std::uint32_t i : loop) by_angle.emplace_back(std::atan2((v[i] - c).dot(w), (v[i] - c).dot(u)), i);
  std::sort(by_angle.begin(), by_angle.end());
  for (std::size_t k = 0; k < loop.size(); ++k) loop[k] = by_angle[k].second;
}

// The plane through a loop: normal from the summed fan cross products (exact for
// axis-aligned faces), offset from the outermost vertex so every vertex is inside.
Plane plane_of(const std::vector<std::uint32_t>& loop, const std::vector<Eigen::Vector3d>& v) {
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  for (std::size_t k = 1; k + 1 < loop.size(); ++k) n += (v[loop[k]] - v[loop[0]]).cross(v[loop[k + 1]] - v[loop[0]]);
  n.normalize();
  double offset = -std::numeric_limits<double>::infinity();
  for (std::uint32_t i : loop) offset = std::max(offset, n.dot(v[i]));
  return {n, offset};
}

}  // namespace

ConvexHull::ConvexHull(std::span<const Eigen::Vector3d> points) {
  const std::vector<Eigen::Vector3d> input(points.begin(), points.end());
  detail::QhullFacets hull = detail::qhull_convex_hull(input);

  // Keep only the hull vertices, renumbered.
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::uint32_t> renumber(input.size());
  for (std::uint32_t id : hull.vertices) {
    renumber[id] = static_cast<std::uint32_t>(vertices.size());
    vertices.push_back(input[id]);
  }
  std::vector<std::vector<std::uint32_t>> faces;
  std::vector<Triangle> triangles;
  for (std::size_t f = 0; f < hull.facets.size(); ++f) {
    std::vector<std::uint32_t> loop;
    for (std::uint32_t id : hull.facets[f]) loop.push_back(renumber[id]);
    order_loop(loop, vertices, hull.normals[f]);
    for (std::size_t k = 1; k + 1 < loop.size(); ++k) triangles.push_back({loop[0], loop[k], loop[k + 1]});
    faces.push_back(std::move(loop));
  }

  const detail::PolyhedronMass mass = detail::polyhedral_mass(vertices, triangles);
  for (auto& v : vertices) v -= mass.center;
  std::vector<Plane> planes;
  for (const auto& loop : faces) planes.push_back(plane_of(loop, vertices));
  std::vector<std::uint32_t> all(vertices.size());
  std::iota(all.begin(), all.end(), 0u);
  data_ =
      std::make_shared<const Data>(Data{std::move(faces), std::move(planes), mass.center, mass.volume, mass.inertia,
                                        detail::MeshCore(std::move(vertices), std::move(triangles), std::move(all))});
}

const std::vector<Eigen::Vector3d>& ConvexHull::vertices() const { return data_->core.vertices(); }
const std::vector<std::vector<std::uint32_t>>& ConvexHull::faces() const { return data_->faces; }
const std::vector<Plane>& ConvexHull::planes() const { return data_->planes; }
const std::vector<Triangle>& ConvexHull::triangles() const { return data_->core.triangles(); }
const Eigen::Vector3d& ConvexHull::com_shift() const { return data_->com_shift; }
double ConvexHull::volume() const { return data_->volume; }
const Eigen::Matrix3d& ConvexHull::unit_inertia() const { return data_->unit_inertia; }
double ConvexHull::bounding_radius() const { return data_->core.bounding_radius(); }
Aabb ConvexHull::world_aabb(const Pose& pose) const { return data_->core.world_aabb(pose); }
Eigen::Vector3d ConvexHull::support(const Eigen::Vector3d& direction) const { return data_->core.support(direction); }

ConvexHull::NearestPlane ConvexHull::nearest_plane(const Eigen::Vector3d& p) const {
  const auto& planes = data_->planes;
  NearestPlane best{planes[0].distance(p), 0, planes[0].normal};
  for (std::size_t f = 1; f < planes.size(); ++f) {
    const double d = planes[f].distance(p);
    if (d > best.distance)
      best = {d, f, planes[f].normal};
    else if (d == best.distance)
      best.normal_sum += planes[f].normal;
  }
  return best;
}

bool ConvexHull::contains(const Eigen::Vector3d& p) const { return nearest_plane(p).distance <= 0.0; }

double ConvexHull::signed_distance(const Eigen::Vector3d& p) const { return closest(p).distance; }

SurfacePoint ConvexHull::closest(const Eigen::Vector3d& p) const {
  std::uint32_t hint = 0;
  return closest(p, hint);
}

SurfacePoint ConvexHull::closest(const Eigen::Vector3d& p, std::uint32_t& hint) const {
  const NearestPlane inside = nearest_plane(p);
  if (inside.distance <= 0.0) {
    const double d = inside.distance;
    return {d, p - d * data_->planes[inside.face].normal, inside.normal_sum.normalized()};
  }
  SurfacePoint s = data_->core.closest(p, hint);
  if (s.distance < 0.0) {  // the planes decide the side, whatever rounding told the pseudo-normal
    s.distance = -s.distance;
    s.normal = -s.normal;
  }
  return s;
}

}  // namespace cosim::geometry
