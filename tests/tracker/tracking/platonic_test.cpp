// Mean transit distance through a convex cell (Stollmeier & Grabe): 4 V / A_s, on the
// five Platonic solids of unit volume, each a one-cell mesh, by random chords tracked with
// the event-driven algorithm.

#include "tracker/mesh/assemble.hpp"
#include "tracker/mesh/geometry.hpp"
#include "tracker/tracking/move.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <set>

namespace cosim::tracker::tracking {
namespace {

// The convex hull's faces by brute force (at most 20 points): a plane through three
// points with all others on one side is a face; its points, ordered counter-clockwise
// seen from outside, are the loop.
mesh::Polyhedra hull(const std::vector<Vec3>& points) {
  mesh::Polyhedra poly;
  poly.vertices = points;
  std::set<std::vector<Index>> seen;
  const Index n = static_cast<Index>(points.size());
  for (Index i = 0; i < n; ++i)
    for (Index j = i + 1; j < n; ++j)
      for (Index k = j + 1; k < n; ++k) {
        Vec3 normal = (points[j] - points[i]).cross(points[k] - points[i]);
        if (normal.norm() < 1e-9) continue;
        normal.normalize();
        std::vector<Index> on;
        int above = 0, below = 0;
        for (Index m = 0; m < n; ++m) {
          const double d = normal.dot(points[m] - points[i]);
          if (std::abs(d) < 1e-9) on.push_back(m);
          above += d > 1e-9;
          below += d < -1e-9;
        }
        if (above && below) continue;
        if (above) normal = -normal;  // outward
        if (!seen.insert(on).second) continue;
        Vec3 middle = Vec3::Zero();
        for (Index m : on) middle += points[m] / double(on.size());
        const Vec3 e1 = (points[on[0]] - middle).normalized(), e2 = normal.cross(e1);
        const auto angle = [&](Index m) { return std::atan2(e2.dot(points[m] - middle), e1.dot(points[m] - middle)); };
        std::sort(on.begin(), on.end(), [&](Index a, Index b) { return angle(a) < angle(b); });
        poly.add_face(on);
      }
  poly.end_cell();
  poly.source = "hull";
  return poly;
}

struct Solid {
  const char* name;
  std::vector<Vec3> vertices;
};

std::vector<Vec3> cyclic(const std::vector<Vec3>& points) {
  std::vector<Vec3> all;
  for (const Vec3& p : points)
    for (int k = 0; k < 3; ++k) all.emplace_back(p[k], p[(k + 1) % 3], p[(k + 2) % 3]);
  return all;
}

std::vector<Solid> platonic_solids() {
  const double phi = std::numbers::phi;
  std::vector<Vec3> cube, icosahedron, dodecahedron;
  for (double a : {-1.0, 1.0})
    for (double b : {-1.0, 1.0}) {
      for (double c : {-1.0, 1.0}) cube.emplace_back(a, b, c);
      icosahedron.emplace_back(0.0, a, b * phi);
      dodecahedron.emplace_back(0.0, a / phi, b * phi);
    }
  dodecahedron = cyclic(dodecahedron);
  dodecahedron.insert(dodecahedron.end(), cube.begin(), cube.end());
  return {{"tetrahedron", {Vec3(1, 1, 1), Vec3(1, -1, -1), Vec3(-1, 1, -1), Vec3(-1, -1, 1)}},
          {"cube", cube},
          {"octahedron", cyclic({Vec3(1, 0, 0), Vec3(-1, 0, 0)})},
          {"dodecahedron", dodecahedron},
          {"icosahedron", cyclic(icosahedron)}};
}

mesh::Mesh unit_volume(const Solid& solid) {
  const double volume = mesh::assemble(hull(solid.vertices)).volume[0];
  std::vector<Vec3> scaled;
  for (const Vec3& x : solid.vertices) scaled.push_back(x / std::cbrt(volume));
  return mesh::assemble(hull(scaled));
}

// Uniform isotropic random lines through the solid, by mu-randomness: a point uniform on
// the surface (face by area, then a triangle of the face's fan by area, then uniform in
// the triangle) and a direction cosine-weighted about the inward normal. The chord is the
// way from there to the exit, where the open wall removes the particle.
double mean_chord(const mesh::Mesh& mesh, int chords, std::uint64_t seed) {
  const Boundaries open{std::vector<BoundaryCondition>(mesh.patches.size(), {.kind = BoundaryKind::open}), 0.0};
  const Domain domain(mesh, open);
  Random random(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<double> areas;
  for (Index f = 0; f < mesh.face_count(); ++f) areas.push_back(mesh::area_vector(mesh, f).norm());
  std::discrete_distribution<Index> pick_face(areas.begin(), areas.end());
  double sum = 0.0;
  for (int i = 0; i < chords; ++i) {
    const Index f = pick_face(random);
    const Vec3 middle = mesh::vertex_mean(mesh, f);
    const Index n = mesh.vertex_count(f);
    const Index k = std::uniform_int_distribution<Index>(0, n - 1)(random);  // equal triangles: regular faces
    const double r1 = std::sqrt(uniform(random)), r2 = uniform(random);
    const Vec3 a = mesh.face_vertex(f, k) - middle, b = mesh.face_vertex(f, (k + 1) % n) - middle;
    const Vec3 start = middle + r1 * ((1.0 - r2) * a + r2 * b);
    const Vec3& normal = mesh.faces[f].normal;
    const Vec3 t1 = normal.unitOrthogonal(), t2 = normal.cross(t1);
    const double sine_squared = uniform(random), azimuth = 2.0 * std::numbers::pi * uniform(random);
    const Vec3 direction = std::sqrt(1.0 - sine_squared) * normal +
                           std::sqrt(sine_squared) * (std::cos(azimuth) * t1 + std::sin(azimuth) * t2);
    Particle particle{start, direction, 0};
    const MoveResult result = move(Algorithm::event_driven, domain, particle, 100.0, random);
    EXPECT_TRUE(result.removed);
    sum += (particle.x - start).norm();
  }
  return sum / chords;
}

TEST(TransitDistance, PlatonicSolidsByRandomChords) {
  std::uint64_t seed = 1;
  for (const Solid& solid : platonic_solids()) {
    const mesh::Mesh mesh = unit_volume(solid);
    ASSERT_NEAR(mesh.volume[0], 1.0, 1e-12) << solid.name;
    double surface = 0.0;
    for (Index f = 0; f < mesh.face_count(); ++f) surface += mesh::area_vector(mesh, f).norm();
    const double expected = 4.0 * mesh.volume[0] / surface;
    const double measured = mean_chord(mesh, 200000, seed++);
    const double error = measured / expected - 1.0;
    std::printf("%-13s %2d faces: mean chord %.5f, 4V/A_s %.5f, error %+.3f %%\n", solid.name, mesh.face_count(),
                measured, expected, 100.0 * error);
    EXPECT_LT(std::abs(error), 0.01) << solid.name;
  }
}

}  // namespace
}  // namespace cosim::tracker::tracking
