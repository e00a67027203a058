// Mass properties of meshes and hulls by polyhedral integrals against the analytic shapes:
// exact for polyhedra, converging for tessellations of curved solids.
#include <gtest/gtest.h>

#include <cstdio>

#include "tests/geometry/fixtures.hpp"
#include "geometry/mass_properties.hpp"

namespace cosim::geometry {
namespace {

using testing::MeshArrays;

double relative_error(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) { return (a - b).norm() / b.norm(); }

void expect_same_mass(const Shape& shape, const Shape& reference, double tolerance) {
  const MassProperties m = mass_properties(shape, 3.0), r = mass_properties(reference, 3.0);
  EXPECT_NEAR(m.volume, r.volume, tolerance * r.volume);
  EXPECT_LT(relative_error(m.inertia, r.inertia), tolerance) << m.inertia << "\nexpected\n" << r.inertia;
}

TEST(PolyhedralMass, BoxAsMeshAndHullIsExact) {
  const Eigen::Vector3d h(0.9, 0.4, 0.6);
  const MeshArrays mesh = testing::box_mesh(h);
  std::vector<Eigen::Vector3d> points = mesh.vertices;
  points.emplace_back(0.1, 0.2, -0.3);  // inside: not a hull vertex
  expect_same_mass(testing::make_mesh(mesh), Box(h), 1e-14);
  expect_same_mass(ConvexHull(points), Box(h), 1e-14);
}

// The corner tetrahedron s * {0, e_x, e_y, e_z}: V = s^3/6, centroid s/4 (1,1,1); about the
// centroid I_xx = s^5/80 and I_xy = +s^5/480 per unit density (integrals of x^2 = s^5/60
// and xy = s^5/120 over it, shifted by the parallel-axis theorem).
TEST(PolyhedralMass, OffsetTetrahedronAsMeshAndHullIsExact) {
  const double s = 2.0;
  const Eigen::Vector3d o(1.0, -2.0, 0.5);
  const MeshArrays tet = testing::tetrahedron_mesh(
      {o, o + s * Eigen::Vector3d::UnitX(), o + s * Eigen::Vector3d::UnitY(), o + s * Eigen::Vector3d::UnitZ()});
  Eigen::Matrix3d expected = Eigen::Matrix3d::Constant(std::pow(s, 5) / 480);
  expected.diagonal().setConstant(std::pow(s, 5) / 80);

  const TriangleMesh mesh = testing::make_mesh(tet);
  const ConvexHull hull(tet.vertices);
  for (const auto& [volume, inertia, shift] : {std::tuple{mesh.volume(), mesh.unit_inertia(), mesh.com_shift()},
                                               std::tuple{hull.volume(), hull.unit_inertia(), hull.com_shift()}}) {
    EXPECT_NEAR(volume, s * s * s / 6, 1e-15);
    EXPECT_LT(relative_error(inertia, expected), 1e-14) << inertia;
    EXPECT_LT((shift - (o + Eigen::Vector3d::Constant(s / 4))).norm(), 1e-15);
  }
}

TEST(PolyhedralMass, OffsetRotatedMeshIsShiftedToItsCentreOfMass) {
  const Eigen::Vector3d h(0.9, 0.4, 0.6), offset(5.0, -3.0, 2.0);
  const Eigen::Quaterniond q = Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()));
  MeshArrays moved = testing::box_mesh(h);
  for (auto& v : moved.vertices) v = q * v + offset;
  const TriangleMesh mesh = testing::make_mesh(moved);

  EXPECT_LT((mesh.com_shift() - offset).norm(), 1e-13);
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& v : mesh.vertices()) mean += v;
  EXPECT_LT(mean.norm(), 1e-13);
  const Eigen::Matrix3d r = q.toRotationMatrix();
  EXPECT_LT(relative_error(mesh.unit_inertia(), r * Box(h).unit_inertia() * r.transpose()), 1e-13);
  EXPECT_NEAR(mesh.signed_distance(Eigen::Vector3d::Zero()), -h.minCoeff(), 1e-13);
}

// Inscribed tessellations, as meshes and as hulls: the errors shrink with refinement,
// roughly 4x per halving.
void expect_converges(const char* label, const Shape& reference, const std::vector<MeshArrays>& meshes,
                      double final_tolerance) {
  const MassProperties r = mass_properties(reference, 1.0);
  double previous = 1.0;
  std::printf("%-10s %10s %14s %14s\n", label, "triangles", "volume error", "inertia error");
  for (const MeshArrays& arrays : meshes) {
    const TriangleMesh mesh = testing::make_mesh(arrays);
    const MassProperties m = mass_properties(mesh, 1.0);
    // The tessellations are convex: the hull of their vertices is the same solid.
    const MassProperties h = mass_properties(ConvexHull(arrays.vertices), 1.0);
    EXPECT_NEAR(h.volume, m.volume, 1e-13 * m.volume);
    EXPECT_LT(relative_error(h.inertia, m.inertia), 1e-12);
    const double ev = std::abs(m.volume - r.volume) / r.volume, ei = relative_error(m.inertia, r.inertia);
    std::printf("%-10s %10zu %14.3e %14.3e\n", "", arrays.triangles.size(), ev, ei);
    EXPECT_LT(std::max(ev, ei), previous);
    previous = std::max(ev, ei);
  }
  EXPECT_LT(previous, final_tolerance);
}

TEST(PolyhedralMass, TessellationsConverge) {
  std::vector<MeshArrays> spheres, ellipsoids, cylinders, capsules;
  for (int level = 1; level <= 4; ++level) {
    spheres.push_back(testing::ellipsoid_mesh(Eigen::Vector3d::Constant(0.7), level));
    ellipsoids.push_back(testing::ellipsoid_mesh({1.2, 0.5, 0.8}, level));
  }
  for (int segments : {8, 16, 32, 64}) {
    cylinders.push_back(testing::cylinder_mesh(0.5, 1.6, segments));
    capsules.push_back(testing::capsule_mesh(0.4, 1.0, segments));
  }
  expect_converges("sphere", Sphere(0.7), spheres, 4e-3);
  expect_converges("ellipsoid", Ellipsoid({1.2, 0.5, 0.8}), ellipsoids, 4e-3);
  expect_converges("cylinder", Cylinder(0.5, 1.6), cylinders, 3e-3);
  expect_converges("capsule", Capsule(0.4, 1.0), capsules, 5e-3);
}

}  // namespace
}  // namespace cosim::geometry
