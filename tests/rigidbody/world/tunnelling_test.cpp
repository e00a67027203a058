// Tunnelling: which bodies move too far per substep, and what really happens at the
// scenes' dt (a thin plate thrown at a plane; a fast ball at a thin fixed plate).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "geometry/convex_hull.hpp"
#include "rigidbody/world/tunnelling.hpp"
#include "tests/rigidbody/world/scenes.hpp"

namespace cosim::rigidbody::world::test {
namespace {

using Eigen::Vector3d;

constexpr double plate_half = 0.0025;  // the 0.2 x 0.2 x 0.005 m plate of configs/rigid_thin_box.yaml
const Vector3d plate{0.1, 0.1, plate_half};

TEST(Tunnelling, ThinnestExtentOfEveryShape) {
  EXPECT_DOUBLE_EQ(thinnest_extent(geometry::Sphere(0.1)), 0.2);
  EXPECT_DOUBLE_EQ(thinnest_extent(geometry::Ellipsoid({0.3, 0.05, 0.2})), 0.1);
  EXPECT_DOUBLE_EQ(thinnest_extent(geometry::Box(plate)), 2 * plate_half);
  EXPECT_DOUBLE_EQ(thinnest_extent(geometry::Cylinder(0.1, 0.01)), 0.01);  // a coin
  EXPECT_DOUBLE_EQ(thinnest_extent(geometry::Cylinder(0.01, 0.5)), 0.02);  // a rod
  EXPECT_DOUBLE_EQ(thinnest_extent(geometry::Capsule(0.01, 0.5)), 0.02);
  EXPECT_EQ(thinnest_extent(geometry::HalfSpace(Vector3d::UnitZ())), std::numeric_limits<double>::infinity());
  // A tilted slab 0.01 thick: its body axes see it thick, its faces see it thin.
  const Eigen::Quaterniond tilt(Eigen::AngleAxisd(0.5, Vector3d(1, 1, 0).normalized()));
  std::vector<Vector3d> corners;
  for (int k = 0; k < 8; ++k)
    corners.push_back(tilt * Vector3d((k & 1 ? 1 : -1) * 0.2, (k & 2 ? 1 : -1) * 0.2, (k & 4 ? 1 : -1) * 0.005));
  EXPECT_NEAR(thinnest_extent(geometry::ConvexHull(corners)), 0.01, 1e-12);
}

// Guards against: a body fast enough to tunnel in one substep going unreported.
TEST(Tunnelling, FlagsBodiesFasterThanTheMarginOrHalfTheirThickness) {
  const std::vector<double> thinnest{0.2, 2 * plate_half, 0.2, 2 * plate_half};
  std::vector<dynamics::BodyState> states(4);
  std::vector<dynamics::BodyInertia> inertias(4, dynamics::BodyInertia::of(1.0, Eigen::Matrix3d::Identity(), true));
  inertias[3] = {};  // fixed: never at risk, whatever its velocity says
  const double dt = 1e-3, margin = 0.01;
  states[0].velocity = {0, 0, -5};  // 5 mm per substep: within both limits
  states[1].velocity = {0, 0, -5};  // 5 mm > half the plate's 5 mm thickness
  states[2].velocity = {0, 11, 0};  // 11 mm > the 10 mm margin
  states[3].velocity = {0, 0, -100};
  const auto risks = tunnelling_risks(thinnest, states, inertias, dt, margin, 0.0);
  ASSERT_EQ(risks.size(), 2u);
  EXPECT_EQ(risks[0].body, 1u);
  EXPECT_NEAR(risks[0].travel, 5e-3, 1e-15);
  EXPECT_DOUBLE_EQ(risks[0].thinnest, 2 * plate_half);
  EXPECT_EQ(risks[1].body, 2u);
  EXPECT_DOUBLE_EQ(risks[1].margin, margin);
  // The speed a body may gain in the window counts: the resting ball is caught early.
  states[0].velocity.setZero();
  EXPECT_EQ(tunnelling_risks(thinnest, states, inertias, dt, margin, 10.5)[0].body, 0u);
  const std::string message = describe(risks[0], "plate", dt);
  EXPECT_NE(message.find("body 1 (plate) may move 0.005 m per substep"), std::string::npos) << message;
  EXPECT_NE(message.find("half its thinnest extent 0.0025 m"), std::string::npos) << message;
  EXPECT_EQ(message.find("contact margin"), std::string::npos) << message;
  EXPECT_NE(message.find("lower the rigidbody dt by a factor 2, to 0.0005 s"), std::string::npos) << message;
}

// Guards against: a granular bed flooding the log with one tunnelling warning per body.
TEST(Tunnelling, OneWarningForManyBodiesAndAnotherOnlyWhenTheCountOrTheExcessDoubles) {
  TunnellingWarnings warnings;
  for (int i = 0; i < 40; ++i) warnings.add("grain" + std::to_string(i), geometry::Sphere(0.1));
  const double dt = 1e-3, margin = 0.01;
  const auto risks = [&](std::uint32_t count, double worst) {
    std::vector<TunnellingRisk> out;
    for (std::uint32_t i = 0; i < count; ++i) out.push_back({i, i == 3 ? worst : 0.02, 0.2, margin});
    return out;
  };
  EXPECT_EQ(warnings.warning(risks(5, 0.05), dt),
            "5 bodies may move farther per substep than the contact margin or half their thinnest extent; the worst: "
            "body 3 (grain3) may move 0.05 m per substep (dt = 0.001 s), more than the contact margin 0.01 m: it can "
            "pass through thin bodies or planes; lower the rigidbody dt by a factor 5, to 0.0002 s or raise "
            "participants.rigidbody.options.contact_margin above 0.05 m");
  EXPECT_EQ(warnings.warning(risks(5, 0.05), dt), std::nullopt);
  EXPECT_EQ(warnings.warning(risks(9, 0.09), dt), std::nullopt);
  const std::optional<std::string> twice_the_count = warnings.warning(risks(10, 0.05), dt);
  ASSERT_TRUE(twice_the_count);
  EXPECT_TRUE(twice_the_count->starts_with("10 bodies may move")) << *twice_the_count;
  const std::optional<std::string> twice_the_excess = warnings.warning(risks(10, 0.1), dt);
  ASSERT_TRUE(twice_the_excess);
  EXPECT_NE(twice_the_excess->find("lower the rigidbody dt by a factor 10, to 0.0001 s"), std::string::npos)
      << *twice_the_excess;
  EXPECT_EQ(warnings.warning({}, dt), std::nullopt);
}

// Guards against: the summary hiding how many bodies are at risk in each window, or the
// world logging by itself.
TEST(Tunnelling, TheStepReportCountsEveryWindowAndCarriesTheWarningOnce) {
  World world({.body_forces = {.gravity = false}});
  add_ground(world);
  constexpr int grains = 30;
  for (int i = 0; i < grains; ++i) {
    const auto b = add_sphere(world, 0.01, {0.05 * i, 0, 1.0});
    world.states()[b].velocity = {0, 0, -3};  // 3 mm per substep, above the 1 mm margin
  }
  std::vector<std::string> warnings;
  for (int window = 0; window < 20; ++window) {
    const StepReport report = world.advance(0.01);
    EXPECT_EQ(report.tunnelling_bodies, grains);
    warnings.insert(warnings.end(), report.warnings.begin(), report.warnings.end());
  }
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_TRUE(warnings[0].starts_with("30 bodies may move")) << warnings[0];
}

// configs/rigid_thin_box.yaml: the plate moves 0.05 m per substep, ten times its thickness
// and over three times the default margin. The world flags it, but a half-space reports
// any depth with the right normal, so the plate cannot pass through the plane: it lands
// and rests on it.
// SI pushes the plate out with Baumgarte (its centre is above the plane again by the first
// window's end); the soft step's spring pushes slower (push speed bias_rate x depth), so
// for a few windows the plate is still partly in the plane, never all of it.
// Guards against: a thin fast plate passing through a plane between two substeps.
class ThinPlate : public ::testing::TestWithParam<SolverKind> {};

TEST_P(ThinPlate, At50MetresPerSecondStopsOnAPlane) {
  World world({.solver = GetParam()});  // dt 1e-3, default margin: a tenth of the plate's bounding radius
  add_ground(world);
  const auto b = add_box(world, plate, {0, 0, 0.1});
  world.states()[b].velocity = {0, 0, -50};
  EXPECT_EQ(world.advance(0.01).tunnelling_bodies, 1u);
  const double lowest = GetParam() == SolverKind::soft ? -plate_half : 0.0;
  for (int window = 1; window < 50; ++window) {
    world.advance(0.01);
    ASSERT_GT(world.states()[b].position.z(), lowest) << "window " << window;
  }
  EXPECT_NEAR(world.states()[b].position.z(), plate_half, 0.01 * plate_half);
  EXPECT_LT(world.states()[b].velocity.norm(), 1e-3);
}

INSTANTIATE_TEST_SUITE_P(Tunnelling, ThinPlate, ::testing::Values(SolverKind::soft, SolverKind::sequential_impulses),
                         [](const auto& info) {
                           return info.param == SolverKind::soft ? "Soft" : "SequentialImpulses";
                         });

// A ball at 50 m/s against a fixed 5 mm plate: at dt 1e-3 it jumps the plate between two
// substeps without a contact. The check flags it; at the dt the warning asks for, the ball
// is caught by a speculative contact and bounces back.
// Guards against: the suggested smaller dt not catching a ball that jumps a thin plate.
TEST(Tunnelling, BallThroughAThinPlateIsFlaggedAndStopsAtTheSuggestedDt) {
  constexpr double r = 0.02, v = 50.0;
  const auto shoot = [&](double dt) {
    World world({.dt = dt, .body_forces = {.gravity = false}});
    world.add({.shape = geometry::Box(plate), .fixed = true});
    const auto ball = add_sphere(world, r, {0, 0, 0.125}, {.restitution = 1.0});
    world.states()[ball].velocity = {0, 0, -v};
    const auto report = world.advance(0.004);
    return std::pair{report, world.states()[ball]};
  };
  const auto [fast, through] = shoot(1e-3);
  EXPECT_EQ(fast.tunnelling_bodies, 1u);
  EXPECT_LT(through.position.z(), -0.05);  // sampled at z = 0.025 and -0.025: never within the margin
  EXPECT_DOUBLE_EQ(through.velocity.z(), -v);

  const double margin = 0.1 * r;  // the default: a tenth of the ball's bounding radius
  const auto [slow, bounced] = shoot(0.99 * margin / v);
  EXPECT_EQ(slow.tunnelling_bodies, 0u);
  EXPECT_GT(bounced.position.z(), plate_half + r);
  EXPECT_NEAR(bounced.velocity.z(), v, 1e-6 * v);
}

}  // namespace
}  // namespace cosim::rigidbody::world::test
