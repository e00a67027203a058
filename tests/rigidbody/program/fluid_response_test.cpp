// The fluid's response tensors on the rigid side, against known answers on model fluids
// whose window-mean load lags the motion that causes it by a window, as explicit coupling
// hands it over: with the coupler's Robin wrenches (coupler/participant/robin.hpp) and the
// tensors carried, a body moves as if the load followed its motion at once, whatever its
// mass, where the plain lagged load diverges; a repeated window converges to the coupled
// motion.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "coupler/participant/robin.hpp"
#include "rigidbody/program/adapter.hpp"

namespace cosim::rigidbody::program {
namespace {

constexpr double kFluidDensity = 1000, kRadius = 0.01, kWindow = 0.01, kG = 9.81;
const double kVolume = 4.0 / 3.0 * std::numbers::pi * kRadius * kRadius * kRadius;

// A sphere in a liquid that gravity and buoyancy act on; the load of the model fluid comes
// from the test, as the coupler would hand it over.
scene::Scene sphere_in_liquid(double density) {
  return scene::load_scene_from_string(
      "time: {end: 10.0}\ncoupling: {window: 0.01, scheme: serial-explicit}\n"
      "domain: {min: [-5, -5, -5], max: [5, 5, 5]}\neffects: [gravity, buoyancy]\n"
      "bodies:\n  - {name: ball, shape: {type: sphere, radius: 0.01}, material: {density: " +
      std::to_string(density) +
      "}, position: [0, 0, 0]}\n"
      "participants:\n  rigidbody: {dt: 1.0e-3, options: {fluid_density: 1000}}\n");
}

// A fluid whose load on a velocity change d_j ramped over window j is -K_n d_j in window
// j + n (vertical only): K_0 = A / W + B / 2, K_n = B after it, a pure added mass A and a
// steady drag B; it sends what cosim-fluid sends: the tensors and the load of the next
// window with the velocity held.
struct ModelFluid {
  double added_mass = 0, damping = 0;
  std::vector<double> changes = {};  // d_j, oldest first

  double kernel(std::size_t n) const { return n == 0 ? added_mass / kWindow + damping / 2 : damping; }
  double load() const {
    double f = 0;
    for (std::size_t j = 0; j < changes.size(); ++j) f -= kernel(changes.size() - 1 - j) * changes[j];
    return f;
  }
  participant::ResponseRow response() const {
    participant::ResponseRow r;
    r.added_mass.topLeftCorner<3, 3>() = added_mass * Eigen::Matrix3d::Identity();
    r.added_damping.topLeftCorner<3, 3>() = damping * Eigen::Matrix3d::Identity();
    double hold = load();
    for (std::size_t j = 0; j < changes.size(); ++j) {
      const std::size_t n = changes.size() - 1 - j;
      hold += (kernel(n) - kernel(n + 1)) * changes[j];
    }
    r.hold.force.z() = hold;
    return r;
  }
};

// Windows of explicit coupling: the body moves with the fluid's last load (and, if
// `responses`, its response), then the fluid takes the body's velocity change. Returns the
// velocity at the end of each window.
std::vector<double> explicit_windows(double density, ModelFluid fluid, bool responses, int windows) {
  RigidSolver solver;
  solver.initialise(sphere_in_liquid(density), "rigidbody", {}, {});
  std::vector<double> w{0.0};
  for (int k = 0; k < windows; ++k) {
    participant::Inputs in;
    in.forces_start.emplace_back().force.z() = fluid.load();
    if (responses) {
      in.responses.push_back(fluid.response());
      const participant::Vector6d wrench = participant::robin_wrench(in.responses[0], {0, 0, w.back(), 0, 0, 0});
      in.forces_start[0] = {wrench.head<3>(), wrench.tail<3>()};
    }
    in.forces_end = in.forces_start;
    const auto out = solver.advance({static_cast<std::uint64_t>(k), 1, k * kWindow, (k + 1) * kWindow}, in);
    fluid.changes.push_back(out.poses.at(0).velocity.z() - w.back());
    w.push_back(out.poses[0].velocity.z());
  }
  return w;
}

// Guards against: the response not taking the lagging added mass into the body's inertia.
// A body of a twentieth of the fluid's density with the sphere's added mass rho_f V / 2 (ten
// times its own): the plain lagged load turns the acceleration over every window, growing
// tenfold; with the response the body rises at the coupled acceleration (m - rho_f V) g /
// (m + A) from the first window on.
TEST(FluidResponse, ALaggingAddedMassNoLongerFeedsBack) {
  const double density = 50, mass = density * kVolume;
  const ModelFluid fluid{.added_mass = 0.5 * kFluidDensity * kVolume};
  const double exact = (kFluidDensity * kVolume - mass) * kG / (mass + fluid.added_mass);
  const std::vector<double> plain = explicit_windows(density, fluid, false, 12);
  const std::vector<double> held = explicit_windows(density, fluid, true, 12);
  EXPECT_GT(std::abs(plain.back()), 1e6 * exact * 12 * kWindow);
  for (std::size_t k = 1; k < held.size(); ++k)
    EXPECT_NEAR(held[k], exact * static_cast<double>(k) * kWindow, 1e-9 * exact) << "window " << k;
}

// Guards against: a drag far stiffer than a window (B W / m = 20) fed back explicitly. The
// plain lagged drag overshoots and diverges; with the response the body approaches its
// terminal velocity (m - rho_f V) g / B monotonically and reaches it.
TEST(FluidResponse, AStiffLaggingDragIsTakenImplicitly) {
  const double density = 500, mass = density * kVolume;
  const ModelFluid fluid{.damping = 20 * mass / kWindow};
  const double terminal = (kFluidDensity * kVolume - mass) * kG / fluid.damping;
  const std::vector<double> plain = explicit_windows(density, fluid, false, 20);
  const std::vector<double> held = explicit_windows(density, fluid, true, 20);
  EXPECT_GT(std::abs(plain.back()), 100 * terminal);
  for (std::size_t k = 1; k < held.size(); ++k) {
    EXPECT_GE(held[k], held[k - 1] - 1e-15) << "window " << k;
    EXPECT_LE(held[k], terminal * (1 + 1e-9)) << "window " << k;
  }
  EXPECT_NEAR(held.back(), terminal, 1e-6 * terminal);
}

// Guards against: a repeated window (implicit coupling) not converging to the coupled
// motion when the response is not the fluid's exact one. The fluid's true added mass is
// 1.5 times the one it sends; each repetition gets the Robin wrench of the previous one's
// load and motion (unaccelerated), and the velocity converges to the coupled
// (m - rho_f V) g W / (m + A_true), the error shrinking by |A_true - A| / (m + A) per
// iteration.
TEST(FluidResponse, ARepeatedWindowConvergesToTheCoupledMotion) {
  const double density = 100, mass = density * kVolume, sent = 0.5 * kFluidDensity * kVolume, truth = 1.5 * sent;
  const double coupled = (kFluidDensity * kVolume - mass) * kG * kWindow / (mass + truth);
  const double rate = std::abs(truth - sent) / (mass + sent);
  RigidSolver solver;
  solver.initialise(sphere_in_liquid(density), "rigidbody", {}, {});
  const std::vector<double> start = solver.state();
  ModelFluid fluid{.added_mass = sent};
  const participant::ResponseRow response = fluid.response();
  participant::Vector6d wrench = participant::robin_wrench(response, participant::Vector6d::Zero());
  double error = 0;
  for (std::uint32_t iteration = 1; iteration <= 12; ++iteration) {
    solver.restore(start);
    participant::Inputs in;
    in.forces_start.push_back({wrench.head<3>(), wrench.tail<3>()});
    in.forces_end = in.forces_start;
    in.responses.push_back(response);
    const double w = solver.advance({0, iteration, 0.0, kWindow}, in).poses.at(0).velocity.z();
    // The window's load for this motion from rest, and the next wrench, as the coupler forms it.
    const participant::ForceRow load{{0, 0, -truth * w / kWindow}, {0, 0, 0}};
    wrench = participant::robin_wrench(response, load, participant::Vector6d::Zero(), {0, 0, w, 0, 0, 0}, kWindow);
    const double next = std::abs(w - coupled);
    if (iteration > 2) {
      EXPECT_NEAR(next / error, rate, 1e-6) << "iteration " << iteration;
    }
    error = next;
  }
  EXPECT_LT(error, 1e-4 * coupled);
}

}  // namespace
}  // namespace cosim::rigidbody::program
