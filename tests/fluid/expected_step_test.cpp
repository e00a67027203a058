// The step cosim-fluid expects a run to take, for the estimate before it
// (fluid_work.hpp): the speed a free body settles at, the controller's steps per window,
// and the step the work report gives for a settling sphere and for a flow past a body.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "fluid/navier_stokes/time_step_controller.hpp"
#include "fluid/program/fluid_work.hpp"
#include "fluid/program/settling_speed.hpp"

namespace cosim::fluid::program {
namespace {

const fluid::viscous::ViscosityModel kOil = fluid::viscous::ViscosityModel::newtonian(0.058);

// ten Cate et al. (2002), case E4: d = 15 mm, 1120 kg/m^3 in 960 kg/m^3 silicone oil of
// 0.058 Pa s; measured u_inf = 0.128 m/s in a box 6.7 diameters wide.
TEST(SettlingSpeed, TenCatesSphereSettlesAtItsMeasuredSpeed) {
  EXPECT_NEAR(settling_speed(0.015, 1120, 960, kOil, 9.81), 0.128, 0.128 * 0.03);
}

TEST(SettlingSpeed, ASmallSphereSettlesAtStokessSpeed) {
  const double a = 1e-4, speed = settling_speed(2 * a, 1120, 960, kOil, 9.81);
  EXPECT_NEAR(speed, 2.0 / 9 * 160 * 9.81 * a * a / 0.058, 1e-3 * speed);
}

TEST(SettlingSpeed, AHeavyBallSettlesAtNewtonsSpeed) {
  // Re far above 1000: C_D = 0.44, so speed^2 = 4 g d (rho_b - rho_f) / (3 * 0.44 rho_f).
  const double d = 0.05, speed = settling_speed(d, 7800, 1000, fluid::viscous::ViscosityModel::newtonian(1e-3), 9.81);
  EXPECT_NEAR(speed, std::sqrt(4 * 9.81 * d * 6800 / (3 * 0.44 * 1000)), 1e-6 * speed);
}

TEST(SettlingSpeed, ABodyAsDenseAsTheFluidOrWithoutGravityStays) {
  EXPECT_EQ(settling_speed(0.015, 960, 960, kOil, 9.81), 0);
  EXPECT_EQ(settling_speed(0.015, 1120, 960, kOil, 0), 0);
  // A lighter body rises as fast as an equally heavier one sinks.
  EXPECT_DOUBLE_EQ(settling_speed(0.015, 800, 960, kOil, 9.81), settling_speed(0.015, 1120, 960, kOil, 9.81));
}

fluid::navier_stokes::TimeStepController controller(double window) {
  return fluid::navier_stokes::TimeStepController({.cfl = 0.5, .dt_max = window, .dt_initial = window});
}

TEST(StepsPerWindow, AStepTheWindowAllowsIsOnePerWindow) {
  EXPECT_DOUBLE_EQ(controller(0.01).steps_per_window(0, 0.01, 100), 1);
  EXPECT_DOUBLE_EQ(controller(0.01).steps_per_window(0.5 / 0.02, 0.01, 100), 1);  // CFL allows 0.02
}

TEST(StepsPerWindow, AWholeNumberOfCflStepsFillsTheWindow) {
  // CFL step a quarter of the window: after the first window's growth from half of it.
  EXPECT_NEAR(controller(0.01).steps_per_window(0.5 / 0.0025, 0.01, 1000), 4, 0.01);
}

TEST(StepsPerWindow, AStepJustShortOfTheWindowSplitsItInTwo) {
  // 1.67 of 2 ms: two steps of 1 ms each (never a sliver after a full step), and from
  // each window's 1 ms last step the growth limit allows only 1.2 ms, so two again.
  EXPECT_DOUBLE_EQ(controller(0.002).steps_per_window(0.5 / 0.00167, 0.002, 275), 2);
}

TEST(StepsPerWindow, TheFirstWindowGrowsFromTheFirstStep) {
  // From 1 % of the window, growing by 1.2 a step towards a CFL step of 0.3: 17 steps
  // (0.01, 0.012, ... 0.128, then the rest in two); the second 5, later ones 4.
  fluid::navier_stokes::TimeStepController c({.cfl = 0.5, .dt_max = 1, .dt_initial = 0.01});
  EXPECT_DOUBLE_EQ(c.steps_per_window(0.5 / 0.3, 1, 1), 17);
  EXPECT_NEAR(c.steps_per_window(0.5 / 0.3, 1, 1000), (17 + 5 + 998 * 4) / 1000.0, 1e-9);
}

std::string sphere_scene(const std::string& body, const std::string& faces) {
  return "time: {end: 1.0}\n"
         "coupling: {window: 0.01, scheme: serial-implicit}\n"
         "gravity: [0, 0, -9.81]\n"
         "domain: {min: [0, 0, 0], max: [0.1, 0.1, 0.16]}\n"
         "effects: [gravity, buoyancy, hydrodynamics, contact]\n"
         "bodies:\n"
         "  - {name: ball, shape: {type: sphere, radius: 0.0075}, material: {density: 1120}, " +
         body +
         "position: [0.05, 0.05, 0.1]}\n"
         "participants:\n"
         "  rigidbody: {dt: 0.001}\n"
         "  fluid:\n"
         "    dt: 0.01\n"
         "    options:\n"
         "      density: 960\n"
         "      viscosity: {model: newtonian, mu: 0.058}\n"
         "      grid: {cells: [40, 40, 64]}\n"
         "      dt_initial: 0.01\n" +
         faces;
}

double expected_dt(const std::string& text) {
  const scene::Scene scene = scene::load_scene_from_string(text, "s.yaml");
  return fluid_work(fluid_setup(scene), scene).dt;
}

TEST(FluidWork, AFreeSphereIsExpectedToSettleAtItsSpeed) {
  // h = 2.5 mm, settling at about 0.129 m/s: the CFL step 0.5 h / u = 9.7 ms, within a
  // window of 10 ms two steps of 5 ms.
  const double u = settling_speed(0.015, 1120, 960, kOil, 9.81);
  ASSERT_LT(0.5 * 0.0025 / u, 0.01);
  EXPECT_DOUBLE_EQ(expected_dt(sphere_scene("", "")), 0.005);
  // Held fixed, it leaves the fluid at rest: a step per window.
  EXPECT_DOUBLE_EQ(expected_dt(sphere_scene("fixed: true, ", "")), 0.01);
}

TEST(FluidWork, AFlowPastABodySpeedsUpByThePotentialFlowsFactor) {
  // Inflow 0.05 m/s along z: 0.05 / 2.5 mm = 20 / s alone, 1.5 times that past the
  // sphere, so the CFL step 0.5 / 30 s, 16.7 ms, still above the 10 ms window; 0.2 m/s
  // gives 0.5 / 120 s = 4.2 ms, three steps per window.
  const auto faces = [](double w) {
    return "      boundaries:\n"
           "        z_min: {type: inflow, velocity: [0, 0, " +
           std::to_string(w) +
           "]}\n"
           "        z_max: {type: outflow}\n";
  };
  EXPECT_DOUBLE_EQ(expected_dt(sphere_scene("fixed: true, ", faces(0.05))), 0.01);
  EXPECT_NEAR(expected_dt(sphere_scene("fixed: true, ", faces(0.2))), 0.01 / 3, 1e-4);
}

}  // namespace
}  // namespace cosim::fluid::program
