#include "tests/geometry/fixtures.hpp"

#include <Eigen/Geometry>
#include <cstdint>
#include <fstream>
#include <map>
#include <numbers>

#include "geometry/queries.hpp"

namespace cosim::geometry::testing {
namespace {

// Makes every triangle of a convex mesh face away from the vertex mean (an interior point).
MeshArrays oriented_convex(MeshArrays mesh) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& v : mesh.vertices) mean += v;
  mean /= static_cast<double>(mesh.vertices.size());
  for (auto& t : mesh.triangles) {
    const auto &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    if ((b - a).cross(c - a).dot((a + b + c) / 3.0 - mean) < 0.0) std::swap(t[1], t[2]);
  }
  return mesh;
}

MeshArrays icosahedron() {
  const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
  MeshArrays m;
  for (double s : {-1.0, 1.0})
    for (double t : {-phi, phi}) {
      m.vertices.emplace_back(0.0, s, t);
      m.vertices.emplace_back(s, t, 0.0);
      m.vertices.emplace_back(t, 0.0, s);
    }
  // The faces are the triples of mutually adjacent vertices (edge length 2).
  const auto adjacent = [&](std::uint32_t i, std::uint32_t j) {
    return std::abs((m.vertices[i] - m.vertices[j]).norm() - 2.0) < 1e-9;
  };
  for (std::uint32_t i = 0; i < 12; ++i)
    for (std::uint32_t j = i + 1; j < 12; ++j)
      for (std::uint32_t k = j + 1; k < 12; ++k)
        if (adjacent(i, j) && adjacent(j, k) && adjacent(i, k)) m.triangles.push_back({i, j, k});
  return oriented_convex(m);
}

MeshArrays subdivided(const MeshArrays& mesh) {
  MeshArrays out{mesh.vertices, {}};
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoint;
  const auto mid = [&](std::uint32_t a, std::uint32_t b) {
    const auto key = std::minmax(a, b);
    const auto [it, inserted] = midpoint.try_emplace(key, static_cast<std::uint32_t>(out.vertices.size()));
    if (inserted) out.vertices.push_back(0.5 * (mesh.vertices[a] + mesh.vertices[b]));
    return it->second;
  };
  for (const auto& t : mesh.triangles) {
    const std::uint32_t ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
    out.triangles.push_back({t[0], ab, ca});
    out.triangles.push_back({ab, t[1], bc});
    out.triangles.push_back({ca, bc, t[2]});
    out.triangles.push_back({ab, bc, ca});
  }
  return out;
}

}  // namespace

MeshArrays box_mesh(const Eigen::Vector3d& h) {
  MeshArrays m;
  for (int i = 0; i < 8; ++i)
    m.vertices.emplace_back(i & 1 ? h.x() : -h.x(), i & 2 ? h.y() : -h.y(), i & 4 ? h.z() : -h.z());
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      // The face's corners in cyclic order around it.
      const int b = 1 << ((axis + 1) % 3), c = 1 << ((axis + 2) % 3), base = side << axis;
      const std::uint32_t q[4] = {std::uint32_t(base), std::uint32_t(base + b), std::uint32_t(base + b + c),
                                  std::uint32_t(base + c)};
      m.triangles.push_back({q[0], q[1], q[2]});
      m.triangles.push_back({q[0], q[2], q[3]});
    }
  return oriented_convex(m);
}

MeshArrays tetrahedron_mesh(const std::array<Eigen::Vector3d, 4>& corners) {
  return oriented_convex({{corners.begin(), corners.end()}, {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}}});
}

MeshArrays ellipsoid_mesh(const Eigen::Vector3d& radii, int levels) {
  MeshArrays m = icosahedron();
  for (int l = 0; l < levels; ++l) m = subdivided(m);
  for (auto& v : m.vertices) v = v.normalized().cwiseProduct(radii);
  return m;
}

MeshArrays revolve(const std::vector<Eigen::Vector2d>& profile, int segments) {
  MeshArrays m;
  const auto rings = static_cast<std::uint32_t>(profile.size() - 2);
  const auto n = static_cast<std::uint32_t>(segments);
  m.vertices.emplace_back(0.0, 0.0, profile.front().y());
  for (std::uint32_t k = 1; k <= rings; ++k)
    for (std::uint32_t s = 0; s < n; ++s) {
      const double a = 2.0 * std::numbers::pi * s / n;
      m.vertices.emplace_back(profile[k].x() * std::cos(a), profile[k].x() * std::sin(a), profile[k].y());
    }
  m.vertices.emplace_back(0.0, 0.0, profile.back().y());
  const std::uint32_t top = static_cast<std::uint32_t>(m.vertices.size() - 1);
  const auto ring = [&](std::uint32_t k, std::uint32_t s) { return 1 + (k - 1) * n + s % n; };
  for (std::uint32_t s = 0; s < n; ++s) {
    m.triangles.push_back({0, ring(1, s), ring(1, s + 1)});
    for (std::uint32_t k = 1; k < rings; ++k) {
      m.triangles.push_back({ring(k, s), ring(k + 1, s), ring(k + 1, s + 1)});
      m.triangles.push_back({ring(k, s), ring(k + 1, s + 1), ring(k, s + 1)});
    }
    m.triangles.push_back({top, ring(rings, s), ring(rings, s + 1)});
  }
  return oriented_convex(m);
}

MeshArrays cylinder_mesh(double radius, double height, int segments) {
  const double h = height / 2;
  return revolve({{0, -h}, {radius, -h}, {radius, h}, {0, h}}, segments);
}

MeshArrays capsule_mesh(double radius, double height, int segments) {
  std::vector<Eigen::Vector2d> profile;
  const int quarter = segments / 4;
  for (double end : {-height / 2, height / 2})
    for (int i = 0; i <= quarter; ++i) {
      const double a = (end < 0 ? -0.5 : 0.0) * std::numbers::pi + 0.5 * std::numbers::pi * i / quarter;
      profile.emplace_back(radius * std::cos(a), end + radius * std::sin(a));
    }
  profile.front().x() = profile.back().x() = 0.0;  // exact poles
  return revolve(profile, segments);
}

MeshArrays torus_mesh(double R, double r, int nu, int nv) {
  MeshArrays m;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double u = 2.0 * std::numbers::pi * i / nu, v = 2.0 * std::numbers::pi * j / nv;
      m.vertices.emplace_back((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u),
                              r * std::sin(v));
    }
  const auto id = [&](int i, int j) { return static_cast<std::uint32_t>((i % nu) * nv + j % nv); };
  // (d/du x d/dv) points out of the tube, so (u, v)-ordered corners face outward.
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

double torus_distance(double R, double r, const Eigen::Vector3d& p) {
  return Eigen::Vector2d(std::hypot(p.x(), p.y()) - R, p.z()).norm() - r;
}

MeshArrays translated(MeshArrays mesh, const Eigen::Vector3d& offset) {
  for (auto& v : mesh.vertices) v += offset;
  return mesh;
}

MeshArrays flipped(MeshArrays mesh) {
  for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
  return mesh;
}

TriangleMesh make_mesh(const MeshArrays& mesh) { return TriangleMesh(mesh.vertices, mesh.triangles, "test mesh"); }

Eigen::Quaterniond random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> g;
  return Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)).normalized();
}

Pose random_pose(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  return Pose(Eigen::Vector3d(u(rng), u(rng), u(rng)), random_rotation(rng));
}

Eigen::Vector3d random_unit(std::mt19937& rng) {
  std::normal_distribution<double> g;
  return Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized();
}

Eigen::Vector3d random_in_ball(std::mt19937& rng, double radius) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  return radius * std::cbrt(u(rng)) * random_unit(rng);
}

std::vector<Eigen::Vector3d> surface_samples(const Shape& shape, int count, std::mt19937& rng) {
  const double reach = 1.5 * bounding_radius(shape);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < count; ++i) points.push_back(closest_point(shape, random_in_ball(rng, reach)).point);
  return points;
}

std::vector<std::pair<std::string, Shape>> bounded_shapes() {
  std::mt19937 rng(7);
  std::vector<Eigen::Vector3d> cloud;
  for (int i = 0; i < 60; ++i) cloud.push_back(random_in_ball(rng, 0.8) + Eigen::Vector3d(0.3, -0.2, 0.1));
  return {{"sphere", Sphere(0.7)},
          {"ellipsoid", Ellipsoid({1.2, 0.5, 0.8})},
          {"box", Box({0.9, 0.4, 0.6})},
          {"cylinder", Cylinder(0.5, 1.6)},
          {"capsule", Capsule(0.4, 1.0)},
          {"hull", ConvexHull(cloud)},
          {"torus mesh", make_mesh(torus_mesh(1.0, 0.3, 24, 12))}};
}

TempDir::TempDir() {
  std::random_device seed;
  path_ = std::filesystem::temp_directory_path() / ("cosim-geometry-" + std::to_string(seed()));
  std::filesystem::create_directories(path_);
}

TempDir::~TempDir() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

void write_ascii_stl(const std::filesystem::path& file, const MeshArrays& mesh) {
  std::ofstream out(file);
  out.precision(17);
  out << "solid test\n";
  for (const auto& t : mesh.triangles) {
    out << " facet normal 0 0 0\n  outer loop\n";
    for (auto i : t) out << "   vertex " << mesh.vertices[i].transpose() << "\n";
    out << "  endloop\n endfacet\n";
  }
  out << "endsolid test\n";
}

void write_binary_stl(const std::filesystem::path& file, const MeshArrays& mesh) {
  std::ofstream out(file, std::ios::binary);
  std::string header = "binary STL written by the cosim geometry tests";  // must not start with "solid"
  header.resize(80, ' ');
  out.write(header.data(), 80);
  const auto count = static_cast<std::uint32_t>(mesh.triangles.size());
  out.write(reinterpret_cast<const char*>(&count), 4);
  for (const auto& t : mesh.triangles) {
    float record[12] = {};
    for (int k = 0; k < 3; ++k)
      for (int a = 0; a < 3; ++a) record[3 + 3 * k + a] = static_cast<float>(mesh.vertices[t[k]][a]);
    const std::uint16_t attributes = 0;
    out.write(reinterpret_cast<const char*>(record), sizeof record);
    out.write(reinterpret_cast<const char*>(&attributes), 2);
  }
}

void write_obj(const std::filesystem::path& file, const MeshArrays& mesh) {
  std::ofstream out(file);
  out.precision(17);
  for (const auto& v : mesh.vertices) out << "v " << v.transpose() << "\n";
  for (const auto& t : mesh.triangles) out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << "\n";
}

}  // namespace cosim::geometry::testing
