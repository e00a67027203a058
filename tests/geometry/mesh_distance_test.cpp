// Mesh signed distance against the analytic distance of the solid it approximates, and the
// robustness of the pseudo-normal sign at edges and vertices.
#include <gtest/gtest.h>

#include <numbers>

#include "tests/geometry/fixtures.hpp"
#include "geometry/detail/closest_on_triangle.hpp"
#include "geometry/queries.hpp"

namespace cosim::geometry {
namespace {

// Largest distance from the mesh surface to the exact surface, over points spread on every
// triangle: the tessellation error, which bounds |mesh distance - exact distance|.
template <class Exact>
double tessellation_error(const TriangleMesh& mesh, const Exact& exact) {
  double worst = 0.0;
  for (const auto& t : mesh.triangles())
    for (int i = 0; i <= 6; ++i)
      for (int j = 0; i + j <= 6; ++j) {
        const Eigen::Vector3d x = mesh.vertices()[t[0]] + (mesh.vertices()[t[1]] - mesh.vertices()[t[0]]) * (i / 6.0) +
                                  (mesh.vertices()[t[2]] - mesh.vertices()[t[0]]) * (j / 6.0);
        worst = std::max(worst, std::abs(exact(x)));
      }
  return worst;
}

template <class Exact>
void expect_close_to_exact(const TriangleMesh& mesh, const Exact& exact, double reach, double tolerance) {
  std::mt19937 rng(9);
  int near_surface = 0;
  for (int i = 0; i < 5000; ++i) {
    const Eigen::Vector3d p = testing::random_in_ball(rng, reach);
    const double d = mesh.signed_distance(p), e = exact(p);
    EXPECT_NEAR(d, e, tolerance) << p.transpose();
    if (std::abs(e) > tolerance) {
      EXPECT_EQ(d < 0.0, e < 0.0) << p.transpose();
    }
    near_surface += std::abs(e) < 0.1;
  }
  EXPECT_GT(near_surface, 100);  // the comparison did probe the surface region
}

TEST(MeshDistance, IcosphereMatchesTheSphereWithinTheTessellationError) {
  const double r = 0.7;
  const TriangleMesh mesh = testing::make_mesh(testing::ellipsoid_mesh(Eigen::Vector3d::Constant(r), 3));
  const auto exact = [&](const Eigen::Vector3d& p) { return p.norm() - r; };
  const double error = tessellation_error(mesh, exact);
  EXPECT_LT(error, 0.01);
  expect_close_to_exact(mesh, exact, 1.5 * r, 1.01 * error);
}

// Non-convex: the inner equator of a torus has concave edges and saddle vertices.
TEST(MeshDistance, TorusMatchesTheTorusWithinTheTessellationError) {
  const double R = 1.0, r = 0.3;
  const TriangleMesh mesh = testing::make_mesh(testing::torus_mesh(R, r, 64, 32));
  const auto exact = [&](const Eigen::Vector3d& p) { return testing::torus_distance(R, r, p); };
  const double error = tessellation_error(mesh, exact);
  EXPECT_LT(error, 0.01);
  expect_close_to_exact(mesh, exact, 1.6, 1.05 * error);
}

// Independent of pseudo-normals: the sum of the solid angles of the triangles seen from p
// (van Oosterom & Strackee), 1 inside a closed outward surface and 0 outside.
double winding_number(const TriangleMesh& mesh, const Eigen::Vector3d& p) {
  double sum = 0.0;
  for (const auto& t : mesh.triangles()) {
    const Eigen::Vector3d a = mesh.vertices()[t[0]] - p, b = mesh.vertices()[t[1]] - p, c = mesh.vertices()[t[2]] - p;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    sum += 2.0 * std::atan2(a.dot(b.cross(c)), la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la);
  }
  return sum / (4.0 * std::numbers::pi);
}

// Points a hair off every vertex and edge midpoint, along the pseudo-normal, against it and
// along random directions, at convex, concave and saddle features: the sign is the side
// given by the winding number.
// Guards against: the wrong inside/outside sign a hair off a mesh edge or vertex.
TEST(MeshDistance, SignIsRobustAtEdgesAndVertices) {
  const TriangleMesh mesh = testing::make_mesh(testing::torus_mesh(1.0, 0.3, 16, 8));
  std::mt19937 rng(10);
  const double eps = 1e-7;
  int checked = 0;
  for (const auto& t : mesh.triangles())
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d& a = mesh.vertices()[t[k]];
      const Eigen::Vector3d& b = mesh.vertices()[t[(k + 1) % 3]];
      for (const Eigen::Vector3d& x : {a, Eigen::Vector3d(0.5 * (a + b))}) {
        const SurfacePoint on = mesh.closest(x);
        ASSERT_LT(std::abs(on.distance), 1e-15);
        std::vector<Eigen::Vector3d> near{x + eps * on.normal, x - eps * on.normal};
        for (int i = 0; i < 4; ++i) near.push_back(x + eps * testing::random_unit(rng));
        for (const Eigen::Vector3d& p : near) {
          const SurfacePoint s = mesh.closest(p);
          EXPECT_EQ(s.distance<0.0, winding_number(mesh, p)> 0.5) << p.transpose();
          EXPECT_NEAR((p - s.point).norm(), std::abs(s.distance), 1e-15);
          ++checked;
        }
      }
    }
  EXPECT_EQ(checked, 256 * 3 * 2 * 6);
}

// Brute force over all triangles: the tree finds the nearest one.
TEST(MeshDistance, TreeSearchEqualsBruteForce) {
  const TriangleMesh mesh = testing::make_mesh(testing::torus_mesh(1.0, 0.3, 20, 10));
  const auto& v = mesh.vertices();
  std::mt19937 rng(12);
  for (int i = 0; i < 500; ++i) {
    const Eigen::Vector3d p = testing::random_in_ball(rng, 2.0);
    double brute = 1e300;
    for (const auto& t : mesh.triangles())
      brute = std::min(brute, detail::closest_on_triangle(p, v[t[0]], v[t[1]], v[t[2]]).squared_distance);
    EXPECT_NEAR(std::abs(mesh.signed_distance(p)), std::sqrt(brute), 1e-15);
  }
}

}  // namespace
}  // namespace cosim::geometry
