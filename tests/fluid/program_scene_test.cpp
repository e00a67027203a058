// participants.fluid as cosim-fluid reads it: the setup, the prescribed motion, and errors
// that name file, line, key and value.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "fluid/program/scene_fluid.hpp"
#include "tests/fluid/program_scenes.hpp"
#include "coupler/scene/error.hpp"

namespace cosim::fluid::program {
namespace {

using testing::oscillating_cylinder_scene;

FluidSetup setup_of(const std::string& text) { return fluid_setup(scene::load_scene_from_string(text, "s.yaml")); }

// The SceneError a scene raises (failing the test if none).
scene::SceneError error_of(const std::string& text) {
  try {
    setup_of(text);
  } catch (const scene::SceneError& e) {
    return e;
  }
  ADD_FAILURE() << "no SceneError for\n" << text;
  return {"", 0, "", "", ""};
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  text.replace(text.find(from), from.size(), to);
  return text;
}

TEST(FluidScene, ReadsGridFluidBoundariesAndBodies) {
  const FluidSetup s = setup_of(oscillating_cylinder_scene(
      "      cfl: 0.4\n      bodies: {method: staircase, subsamples: 2}\n      petsc: -pressure_pc_type hypre -pressure_ksp_rtol 1e-9\n"
      "      body_force: [1.5, 0, -2]\n      pressure_update: rotational\n"));
  ASSERT_EQ(s.axes.size(), 3u);
  EXPECT_EQ(s.axes[0].cells(), 16);
  EXPECT_EQ(s.axes[1].cells(), 8);
  EXPECT_TRUE(s.axes[2].degenerate());
  EXPECT_FALSE(s.axes[0].periodic());
  EXPECT_DOUBLE_EQ(s.axes[0].hi(), 0.4);
  EXPECT_EQ(s.boundaries[0].kind, fluid::grid::BoundaryKind::wall);
  EXPECT_EQ(s.properties.density, 1000);
  EXPECT_DOUBLE_EQ(s.properties.viscosity(5.0), 0.01);
  EXPECT_EQ(s.properties.body_force, (fluid::grid::Point{1.5, 0, -2}));
  EXPECT_EQ(setup_of(oscillating_cylinder_scene()).properties.body_force, (fluid::grid::Point{0, 0, 0}));
  EXPECT_EQ(s.steps.dt_max, 0.01);
  EXPECT_EQ(s.steps.cfl, 0.4);
  ASSERT_TRUE(std::holds_alternative<fluid::staircase::FbmOptions>(s.body_method));
  EXPECT_EQ(std::get<fluid::staircase::FbmOptions>(s.body_method).subsamples, 2);
  EXPECT_EQ(std::get<fluid::staircase::FbmOptions>(s.body_method).offset, fluid::staircase::kCalibratedSurfaceOffset);
  EXPECT_EQ(s.steps.pressure_update, fluid::navier_stokes::PressureUpdate::rotational);
  EXPECT_EQ(setup_of(oscillating_cylinder_scene()).steps.pressure_update,
            fluid::navier_stokes::PressureUpdate::standard);
  EXPECT_EQ(setup_of(oscillating_cylinder_scene("      pressure_update: exact\n")).steps.pressure_update,
            fluid::navier_stokes::PressureUpdate::exact);
  const PetscFlags flags{{"-pressure_pc_type", "hypre"}, {"-pressure_ksp_rtol", "1e-9"}};
  EXPECT_EQ(s.petsc, flags);
  ASSERT_EQ(s.bodies.size(), 1u);
  EXPECT_EQ(s.bodies[0].pose.position(), Eigen::Vector3d(0.2, 0.1, 0.005));
  EXPECT_EQ(s.ranks, (std::array<int, 3>{0, 0, 0}));  // PETSc's choice
}

// grid.ranks: how the participant's ranks share the axes, their product its `ranks`.
TEST(FluidScene, RanksAlongEachAxis) {
  const std::string two = replaced(oscillating_cylinder_scene(), "  fluid:\n", "  fluid:\n    ranks: 2\n");
  EXPECT_EQ(setup_of(replaced(two, "grid: {cells: [16, 8, 1]}", "grid: {cells: [16, 8, 1], ranks: [1, 2, 1]}")).ranks,
            (std::array<int, 3>{1, 2, 1}));
  const scene::SceneError e =
      error_of(replaced(two, "grid: {cells: [16, 8, 1]}", "grid: {cells: [16, 8, 1], ranks: [2, 2, 1]}"));
  EXPECT_NE(std::string(e.what()).find("product is 4"), std::string::npos) << e.what();
  // More ranks along an axis than it has cells.
  const scene::SceneError thin =
      error_of(replaced(two, "grid: {cells: [16, 8, 1]}", "grid: {cells: [16, 8, 1], ranks: [1, 1, 2]}"));
  EXPECT_NE(std::string(thin.what()).find("at most the axis's cells"), std::string::npos) << thin.what();
  // Without the participant's ranks (standalone under mpirun) the grid checks the count.
  EXPECT_EQ(setup_of(replaced(oscillating_cylinder_scene(), "grid: {cells: [16, 8, 1]}",
                              "grid: {cells: [16, 8, 1], ranks: [2, 1, 1]}"))
                .ranks,
            (std::array<int, 3>{2, 1, 1}));
}

// The immersed boundary unless the scene asks for the staircase; its options under bodies.
TEST(FluidScene, BodyMethodAndItsOptions) {
  const FluidSetup plain = setup_of(oscillating_cylinder_scene());
  ASSERT_TRUE(std::holds_alternative<fluid::ibm::IbmOptions>(plain.body_method));
  EXPECT_EQ(std::get<fluid::ibm::IbmOptions>(plain.body_method).kernel, fluid::ibm::DeltaKernel::roma3);
  EXPECT_EQ(std::get<fluid::ibm::IbmOptions>(plain.body_method).retraction->constant,
            fluid::ibm::calibrated_retraction(fluid::ibm::DeltaKernel::roma3).constant);
  const FluidSetup bao = setup_of(oscillating_cylinder_scene("      bodies: {kernel: bao6, tolerance: 1e-8}\n"));
  EXPECT_EQ(std::get<fluid::ibm::IbmOptions>(bao.body_method).retraction->constant,
            fluid::ibm::calibrated_retraction(fluid::ibm::DeltaKernel::bao6).constant);
  EXPECT_EQ(std::get<fluid::ibm::IbmOptions>(bao.body_method).tolerance, 1e-8);
  const FluidSetup set = setup_of(oscillating_cylinder_scene(
      "      bodies: {method: ibm, kernel: peskin4, sweeps: 4, retraction: 0.5, curvature_retraction: 0.1, "
      "marker_spacing: 0.8, spread_at_theta: true}\n"));
  const auto& ibm = std::get<fluid::ibm::IbmOptions>(set.body_method);
  EXPECT_EQ(ibm.kernel, fluid::ibm::DeltaKernel::peskin4);
  EXPECT_EQ(ibm.sweeps, 4);
  EXPECT_EQ(ibm.retraction->constant, 0.5);
  EXPECT_EQ(ibm.retraction->curvature, 0.1);
  EXPECT_EQ(ibm.spacing, 0.8);
  EXPECT_TRUE(ibm.spread_at_theta);
  EXPECT_FALSE(std::get<fluid::ibm::IbmOptions>(plain.body_method).spread_at_theta);
}

TEST(FluidScene, PrescribedMotionIsFixedConstantOrSinusoidal) {
  const FluidSetup s = setup_of(oscillating_cylinder_scene());
  const double t = 0.1, omega = 2 * std::numbers::pi * 2;
  const std::vector<double> p = participant::values_of(poses_at(s.motions, t));
  ASSERT_EQ(p.size(), 13u);
  EXPECT_DOUBLE_EQ(p[0], 0.2 + 0.05 * std::sin(omega * t));
  EXPECT_DOUBLE_EQ(p[7], 0.05 * omega * std::cos(omega * t));
  EXPECT_EQ(p[3], 1.0);  // orientation unchanged

  // Not listed and free: the scene's velocities, constant; listed fixed: at rest.
  std::string free = replaced(oscillating_cylinder_scene(), "fixed: true,",
                              "material: {density: 1000}, velocity: [0.1, 0, 0], angular_velocity: [0, 0, 3.0],");
  free = replaced(free, "      motion: {cyl: {type: sinusoidal, amplitude: [0.05, 0, 0], frequency: 2}}\n", "");
  free += "  rigidbody: {dt: 0.01}\n";
  const std::vector<double> c = participant::values_of(poses_at(setup_of(free).motions, 0.5));
  EXPECT_DOUBLE_EQ(c[0], 0.25);
  EXPECT_NEAR(c[3], std::cos(0.75), 1e-15);  // 1.5 rad about z: w = cos(0.75)
  EXPECT_NEAR(c[6], std::sin(0.75), 1e-15);
  EXPECT_EQ(c[12], 3.0);
  const std::string fixed =
      replaced(free, "participants:\n  fluid:\n    dt: 0.01\n    options:\n",
               "participants:\n  fluid:\n    dt: 0.01\n    options:\n      motion: {cyl: {type: fixed}}\n");
  const std::vector<double> f = participant::values_of(poses_at(setup_of(fixed).motions, 0.5));
  EXPECT_EQ(f[0], 0.2);
  EXPECT_EQ(f[7], 0.0);
}

// Swinging about x by theta(t) = 0.5 sin(2 pi 2 t) from an initial orientation a quarter
// turn about z, while translating: q(t) = (cos(theta/2), sin(theta/2), 0, 0) q0 written out
// (the other order would flip the sign of q_y).
TEST(FluidScene, SinusoidalRotationTurnsAboutAFixedAxis) {
  std::string text = replaced(oscillating_cylinder_scene(), "position: [0.2, 0.1, 0.005]",
                              "position: [0.2, 0.1, 0.005], "
                              "orientation: [0.7071067811865476, 0, 0, 0.7071067811865476]");
  text = replaced(text, "amplitude: [0.05, 0, 0],", "amplitude: [0.05, 0, 0], angular_amplitude: [0.5, 0, 0],");
  const FluidSetup s = setup_of(text);
  const double omega = 2 * std::numbers::pi * 2, r2 = std::sqrt(0.5);
  for (const double t : {0.0, 0.03, 0.1, 0.2, 0.37}) {
    const std::vector<double> p = participant::values_of(poses_at(s.motions, t));
    const double theta = 0.5 * std::sin(omega * t), c = std::cos(theta / 2), si = std::sin(theta / 2);
    EXPECT_NEAR(p[0], 0.2 + 0.05 * std::sin(omega * t), 1e-15) << t;
    const double expected_q[] = {c * r2, si * r2, -si * r2, c * r2};
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(p[3 + i], expected_q[i], 1e-14) << t << " q" << i;
    EXPECT_NEAR(p[7], 0.05 * omega * std::cos(omega * t), 1e-14) << t;
    EXPECT_NEAR(p[10], 0.5 * omega * std::cos(omega * t), 1e-14) << t;
    EXPECT_EQ(p[11], 0.0);
    EXPECT_EQ(p[12], 0.0);
  }
  // Rotation alone: no translation.
  const std::string turning = replaced(text, "amplitude: [0.05, 0, 0], ", "");
  const std::vector<double> r = participant::values_of(poses_at(setup_of(turning).motions, 0.1));
  EXPECT_EQ(r[0], 0.2);
  EXPECT_EQ(r[7], 0.0);
  EXPECT_NEAR(r[10], 0.5 * omega * std::cos(omega * 0.1), 1e-14);
}

struct BadOption {
  const char* from;
  const char* to;
  const char* key;    // SceneError::key ends with it
  const char* value;  // as written
};

TEST(FluidScene, ErrorsNameFileLineKeyAndValue) {
  const std::string good = oscillating_cylinder_scene();
  const BadOption cases[] = {
      {"cells: [16, 8, 1]", "cells: [16.5, 8, 1]", "grid.cells", ""},
      {"cells: [16, 8, 1]", "cells: [16, 0, 1]", "grid.cells", ""},
      {"grid: {cells: [16, 8, 1]}", "grid: {cells: [16, 8, 1], stretch: 1}", "grid.stretch", "1"},
      {"grid: {cells: [16, 8, 1]}", "grid: {cells: [16, 8, 1], ranks: [1, 1, 1.5]}", "grid.ranks", ""},
      {"density: 1000", "density: -1", "density", "-1"},
      {"model: newtonian", "model: bingham", "viscosity.model", "bingham"},
      {"z_max: {type: periodic}", "z_max: {type: wall}", "boundaries.z_max", ""},
      {"z_min: {type: periodic}, ", "z_min: {type: periodic}, x_max: {type: outlet}, ", "boundaries.x_max.type",
       "outlet"},
      {"motion: {cyl:", "motion: {ball:", "motion.ball", ""},
      {"type: sinusoidal,", "type: swinging,", "motion.cyl.type", "swinging"},
      {"frequency: 2", "frequency: 0", "motion.cyl.frequency", "0"},
      {"frequency: 2", "frequency: 2, angular_amplitude: [0, 1]", "motion.cyl.angular_amplitude", ""},
      {"frequency: 2", "frequency: 2, angular_amplitude: [0, 0, x]", "motion.cyl.angular_amplitude", ""},
      {"amplitude: [0.05, 0, 0]", "amplitude: [0, 0, 0]", "motion.cyl.amplitude", "[0, 0, 0]"},
      {"density: 1000", "density: 1000\n      body_force: [1, 0]", "body_force", "[1, 0]"},
      {"density: 1000", "density: 1000\n      petsc: hypre", "petsc", "hypre"},
      {"density: 1000", "density: 1000\n      pressure_update: incremental", "pressure_update", "incremental"},
      {"density: 1000", "density: 1000\n      pressure_update: exact\n      bodies: {method: staircase}",
       "pressure_update", "exact"},
      {"density: 1000", "density: 1000\n      bodies: {method: cutcell}", "bodies.method", "cutcell"},
      {"density: 1000", "density: 1000\n      bodies: {kernel: gauss}", "bodies.kernel", "gauss"},
      {"density: 1000", "density: 1000\n      bodies: {sweeps: 0}", "bodies.sweeps", "0"},
      {"density: 1000", "density: 1000\n      bodies: {method: ibm, subsamples: 2}", "bodies.subsamples", "2"},
      {"density: 1000", "density: 1000\n      bodies: {method: staircase, retraction: 0.3}", "bodies.retraction",
       "0.3"},
      {"density: 1000", "density: 1000\n      subsamples: 2", "subsamples", "2"},
  };
  for (const BadOption& c : cases) {
    const scene::SceneError e = error_of(replaced(good, c.from, c.to));
    EXPECT_EQ(e.file, "s.yaml") << c.to;
    EXPECT_GT(e.line, 0) << c.to;
    EXPECT_TRUE(e.key.ends_with(c.key)) << c.to << ": key " << e.key;
    if (*c.value != 0) {
      EXPECT_EQ(e.value, c.value) << c.to;
    }
    EXPECT_NE(std::string(e.what()).find("s.yaml:"), std::string::npos) << e.what();
  }
}

TEST(FluidScene, RefusesAPlaneBody) {
  std::string text = replaced(
      oscillating_cylinder_scene(), "bodies:\n",
      "bodies:\n  - {name: floor, shape: {type: plane, normal: [0, 1, 0]}, fixed: true, position: [0, 0, 0]}\n");
  const scene::SceneError e = error_of(text);
  EXPECT_EQ(e.key, "bodies[0].shape.type");
  EXPECT_NE(std::string(e.what()).find("wall boundary"), std::string::npos) << e.what();
}

// A fixed body may reach across a periodic face with the immersed boundary, which wraps it
// round; the staircase does not, and a moving body would pass through its part beyond.
TEST(FluidScene, AFixedBodyAcrossAPeriodicFaceNeedsTheImmersedBoundaryAndNoMovingBodies) {
  const std::string across =
      replaced(testing::channel_scene(), "position: [0.2, 0.1, 0.005]", "position: [0.2, 0.01, 0.005]");
  EXPECT_EQ(setup_of(across).bodies.size(), 1u);
  const scene::SceneError staircase =
      error_of(replaced(across, "bodies: {tolerance: 1.0e-9}", "bodies: {method: staircase}"));
  EXPECT_EQ(staircase.key, "bodies[0].position");
  EXPECT_NE(std::string(staircase.what()).find("body 'cyl' reaches across the periodic y faces: the staircase"),
            std::string::npos)
      << staircase.what();
  const std::string with_ball = replaced(
      across, "bodies:\n",
      "bodies:\n  - {name: ball, shape: {type: sphere, radius: 0.005}, material: {density: 2000}, position: [0.1, "
      "0.1, 0.005]}\n");
  const scene::SceneError moving =
      error_of(replaced(with_ball, "participants:\n", "participants:\n  rigidbody:\n    dt: 0.01\n"));
  EXPECT_EQ(moving.key, "bodies[1].position");
  EXPECT_NE(std::string(moving.what()).find("body 'ball' would pass through"), std::string::npos) << moving.what();
  // Wider than the period (0.2 m across y) it would meet itself.
  const scene::SceneError wide = error_of(replaced(across, "radius: 0.03", "radius: 0.11"));
  EXPECT_NE(std::string(wide.what()).find("as long as the period"), std::string::npos) << wide.what();
  // The one-cell periodic axis of a two-dimensional grid has no faces to reach across.
  EXPECT_EQ(setup_of(replaced(replaced(testing::channel_scene(), "height: 0.01", "height: 0.03"),
                              "bodies: {tolerance: 1.0e-9}", "bodies: {method: staircase}"))
                .bodies.size(),
            1u);
}

}  // namespace
}  // namespace cosim::fluid::program
