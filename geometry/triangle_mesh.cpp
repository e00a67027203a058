#include "geometry/triangle_mesh.hpp"

#include <stdexcept>

#include "geometry/detail/mesh_core.hpp"
#include "geometry/detail/mesh_topology.hpp"
#include "geometry/detail/polyhedral_mass.hpp"
#include "geometry/detail/qhull_hull.hpp"

namespace cosim::geometry {

struct TriangleMesh::Data {
  std::string source;
  Eigen::Vector3d com_shift;
  MeshReport report;
  double volume;
  Eigen::Matrix3d unit_inertia;
  detail::MeshCore core;
};

std::string MeshReport::summary() const {
  return std::to_string(merged_vertices) + " duplicate vertices merged, " + std::to_string(dropped_triangles) +
         " collapsed triangles dropped, " + std::to_string(flipped_components) + " components (" +
         std::to_string(flipped_triangles) + " triangles) flipped to face outward";
}

TriangleMesh::TriangleMesh(std::vector<Eigen::Vector3d> vertices, std::vector<Triangle> triangles, std::string source) {
  // Every check below reports what is wrong; the source says which mesh it is about.
  try {
    detail::WeldedMesh welded = detail::weld(vertices, triangles);
    detail::require_nondegenerate(welded.vertices, welded.triangles);
    const auto flipped = detail::orient_outward(welded.vertices, welded.triangles,
                                                detail::edge_neighbors(welded.vertices, welded.triangles));

    MeshReport report{welded.merged_vertices, welded.dropped_triangles, flipped.size(), 0};
    for (std::size_t n : flipped) report.flipped_triangles += n;

    const detail::PolyhedronMass mass = detail::polyhedral_mass(welded.vertices, welded.triangles);
    for (auto& v : welded.vertices) v -= mass.center;
    auto hull = detail::qhull_convex_hull(welded.vertices).vertices;
    data_ = std::make_shared<const Data>(
        Data{source, mass.center, report, mass.volume, mass.inertia,
             detail::MeshCore(std::move(welded.vertices), std::move(welded.triangles), std::move(hull))});
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(source + ": " + e.what());
  }
}

const std::string& TriangleMesh::source() const { return data_->source; }
const std::vector<Eigen::Vector3d>& TriangleMesh::vertices() const { return data_->core.vertices(); }
const std::vector<Triangle>& TriangleMesh::triangles() const { return data_->core.triangles(); }
const Eigen::Vector3d& TriangleMesh::com_shift() const { return data_->com_shift; }
const MeshReport& TriangleMesh::report() const { return data_->report; }
double TriangleMesh::volume() const { return data_->volume; }
const Eigen::Matrix3d& TriangleMesh::unit_inertia() const { return data_->unit_inertia; }
double TriangleMesh::bounding_radius() const { return data_->core.bounding_radius(); }
Aabb TriangleMesh::world_aabb(const Pose& pose) const { return data_->core.world_aabb(pose); }
Eigen::Vector3d TriangleMesh::support(const Eigen::Vector3d& direction) const { return data_->core.support(direction); }

SurfacePoint TriangleMesh::closest(const Eigen::Vector3d& p) const {
  std::uint32_t hint = 0;
  return closest(p, hint);
}

SurfacePoint TriangleMesh::closest(const Eigen::Vector3d& p, std::uint32_t& hint) const {
  return data_->core.closest(p, hint);
}

}  // namespace cosim::geometry
