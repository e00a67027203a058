// Swapping a and b gives the same points with flipped normals, for every pair of kinds;
// nothing is ever NaN.
#include <random>

#include "tests/geometry/fixtures.hpp"
#include "tests/rigidbody/narrowphase/support.hpp"

namespace cosim::rigidbody::narrowphase::testing {
namespace {

using namespace geometry;
using geometry::testing::random_in_ball;
using geometry::testing::random_pose;
using geometry::testing::random_rotation;

std::vector<Shape> shapes() {
  std::vector<Shape> s;
  for (const auto& [name, shape] : geometry::testing::bounded_shapes()) s.push_back(shape);
  s.push_back(geometry::testing::make_mesh(geometry::testing::box_mesh({0.5, 0.7, 0.4})));
  return s;
}

TEST(Symmetry, SwappingFlipsNormalsOnly) {
  std::mt19937 rng(11);
  const auto all = shapes();
  for (const Shape& a : all) {
    for (const Shape& b : all) {
      SCOPED_TRACE(std::string(name(kind(a))) + " - " + std::string(name(kind(b))));
      for (int i = 0; i < 20; ++i) {
        const Pose pa = random_pose(rng);
        const Pose pb(pa.position() + random_in_ball(rng, bounding_radius(a) + bounding_radius(b)),
                      random_rotation(rng));
        const auto ab = contacts(a, pa, b, pb, 0.2), ba = contacts(b, pb, a, pa, 0.2);
        ASSERT_EQ(ab.count, ba.count);
        for (int k = 0; k < ab.count; ++k) {
          const auto& p = ab.points[k];
          const bool matched = std::any_of(ba.points.begin(), ba.points.begin() + ba.count, [&](const auto& q) {
            return (q.position - p.position).norm() < 1e-9 && (q.normal + p.normal).norm() < 1e-9 &&
                   std::abs(q.distance - p.distance) < 1e-9;
          });
          EXPECT_TRUE(matched) << "point " << p.position.transpose();
        }
      }
    }
  }
}

TEST(Symmetry, HalfSpaceAgainstEveryShape) {
  std::mt19937 rng(12);
  const Shape floor = HalfSpace(Vec3::UnitZ());
  for (const Shape& s : shapes()) {
    for (int i = 0; i < 20; ++i) {
      const Pose ps(random_in_ball(rng, 0.5), random_rotation(rng));
      const auto ab = contacts(floor, at(), s, ps, 0.2), ba = contacts(s, ps, floor, at(), 0.2);
      ASSERT_EQ(ab.count, ba.count);
      ASSERT_GE(ab.count, 1);  // every shape reaches below its centre
      for (int k = 0; k < ab.count; ++k) {
        EXPECT_TRUE(ab.points[k].position.isApprox(ba.points[k].position));
        EXPECT_TRUE(ab.points[k].normal.isApprox(-ba.points[k].normal));
      }
      // The deepest point is the shape's support along -n.
      EXPECT_NEAR(min_distance(ab), support(s, ps, -Vec3::UnitZ()).z(), 1e-9);
    }
  }
}

}  // namespace
}  // namespace cosim::rigidbody::narrowphase::testing
