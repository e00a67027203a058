#pragma once

#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "geometry/shape.hpp"

// Meshes of known solids, sampling and temporary files shared by the geometry tests and
// the benchmark.
namespace cosim::geometry::testing {

struct MeshArrays {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Triangle> triangles;
};

MeshArrays box_mesh(const Eigen::Vector3d& half_extents);
MeshArrays tetrahedron_mesh(const std::array<Eigen::Vector3d, 4>& corners);
// Icosahedron subdivided `levels` times, vertices on the sphere (scaled: on the ellipsoid).
MeshArrays ellipsoid_mesh(const Eigen::Vector3d& radii, int levels);
// Surface of revolution about z of a profile (rho, z) running from a pole on the axis to
// the other pole, with `segments` around; vertices lie on the exact surface.
MeshArrays revolve(const std::vector<Eigen::Vector2d>& profile, int segments);
MeshArrays cylinder_mesh(double radius, double height, int segments);
MeshArrays capsule_mesh(double radius, double height, int segments);
// Torus about z: major radius R, minor radius r, nu x nv quads.
MeshArrays torus_mesh(double R, double r, int nu, int nv);
double torus_distance(double R, double r, const Eigen::Vector3d& p);

MeshArrays translated(MeshArrays mesh, const Eigen::Vector3d& offset);
MeshArrays flipped(MeshArrays mesh);
TriangleMesh make_mesh(const MeshArrays& mesh);

Eigen::Quaterniond random_rotation(std::mt19937& rng);
Pose random_pose(std::mt19937& rng);
Eigen::Vector3d random_in_ball(std::mt19937& rng, double radius);
Eigen::Vector3d random_unit(std::mt19937& rng);

// Points of the surface of a bounded shape: closest points of random points in and around
// it (not uniformly spread, but reaching every face, edge and vertex region).
std::vector<Eigen::Vector3d> surface_samples(const Shape& shape, int count, std::mt19937& rng);

// Every analytic and polyhedral bounded shape, for the property tests.
std::vector<std::pair<std::string, Shape>> bounded_shapes();

// A fresh directory under the system temp dir, removed with the object.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

void write_ascii_stl(const std::filesystem::path& file, const MeshArrays& mesh);
void write_binary_stl(const std::filesystem::path& file, const MeshArrays& mesh);
void write_obj(const std::filesystem::path& file, const MeshArrays& mesh);

}  // namespace cosim::geometry::testing
