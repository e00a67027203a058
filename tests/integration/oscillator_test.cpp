// The coupler against the exact answer of the partitioned oscillator: convergence orders
// of the schemes, acceleration, subcycling. Each test runs real processes through
// `cosim run`.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "tests/integration/cosim_process.hpp"
#include "tests/integration/h5_read.hpp"
#include "tests/integration/oscillator_scene.hpp"

namespace cosim::testing {
namespace {

struct Outcome {
  double max_error = 0;  // max |x1 - exact| over all written windows
  double mean_iterations = 0;
  double max_residual = 0;
  Series position;
};

Outcome run_scene(const OscillatorScene& scene, const std::string& name) {
  const auto dir = scratch_dir(name);
  const auto r = run_scene_text(dir, scene.yaml());
  const auto file = dir / "scene.h5";
  EXPECT_EQ(r.exit_code, 0) << r.output;
  Outcome o;
  o.position = read_series(file, "/bodies/m1/position");
  const auto time = read_series(file, "/bodies/m1/time");
  for (std::size_t i = 0; i < time.rows; ++i)
    o.max_error = std::max(o.max_error, std::abs(o.position.at(i, 0) - scene.physics.at(time.at(i))[0]));
  const auto its = read_series(file, "/coupling/iterations");
  const auto res = read_series(file, "/coupling/residual");
  for (std::size_t i = 1; i < its.rows; ++i) {  // row 0 is the initial state
    o.mean_iterations += its.at(i) / static_cast<double>(its.rows - 1);
    o.max_residual = std::max(o.max_residual, res.at(i));
  }
  return o;
}

// Observed order of the error in the window length, halving it twice.
double observed_order(OscillatorScene scene, const std::string& name) {
  std::vector<double> errors;
  for (int level = 0; level < 3; ++level) {
    errors.push_back(run_scene(scene, name + std::to_string(level)).max_error);
    scene.window /= 2;
    scene.dt_mass /= 2;
    scene.dt_spring /= 2;
  }
  const double order = std::log2(errors[1] / errors[2]);
  std::cout << name << ": errors " << errors[0] << ", " << errors[1] << ", " << errors[2] << "  observed order "
            << std::log2(errors[0] / errors[1]) << ", " << order << "\n";
  return order;
}

OscillatorScene base() {
  OscillatorScene s;
  s.end = 1.0;
  s.window = 0.02;
  s.dt_mass = s.dt_spring = 0.002;
  return s;
}

// Explicit schemes hold the inputs constant over a window: first order in W. Implicit
// ones converge the end values and interpolate linearly: the integrators' order, up to 2.
struct OrderCase {
  std::string scheme, integrator;
  double order;
};

void PrintTo(const OrderCase& c, std::ostream* os) { *os << c.scheme << " with " << c.integrator; }

class ObservedOrder : public ::testing::TestWithParam<OrderCase> {};

TEST_P(ObservedOrder, MatchesTheScheme) {
  auto s = base();
  s.scheme = GetParam().scheme;
  s.integrator = GetParam().integrator;
  EXPECT_NEAR(observed_order(s, s.scheme + "_" + s.integrator), GetParam().order, 0.2);
}

INSTANTIATE_TEST_SUITE_P(Oscillator, ObservedOrder,
                         ::testing::Values(OrderCase{"serial-explicit", "verlet", 1.0},
                                           OrderCase{"parallel-explicit", "verlet", 1.0},
                                           OrderCase{"serial-implicit", "verlet", 2.0},
                                           OrderCase{"serial-implicit", "euler", 1.0},
                                           OrderCase{"parallel-implicit", "verlet", 2.0}),
                         [](const auto& info) {
                           auto name = info.param.scheme + "_" + info.param.integrator;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

// A light first mass on a stiff spring (sqrt(k/m1) W = 0.9): the partitioned analogue of
// the added-mass problem of light bodies in a fluid.
OscillatorScene stiff() {
  OscillatorScene s;
  s.physics.m1 = 0.05;
  s.physics.k = 400;
  s.end = 0.5;
  s.window = 0.01;
  s.dt_mass = s.dt_spring = 0.001;
  s.tolerance = 1e-8;
  return s;
}

double max_amplitude(const Series& x) {
  double a = 0;
  for (std::size_t i = 0; i < x.rows; ++i) a = std::max(a, std::abs(x.at(i, 0)));
  return a;
}

// Guards against: implicit coupling failing on the added-mass-like stiff case that explicit coupling cannot
// run.
TEST(Oscillator, StiffCaseDivergesExplicitlyAndConvergesImplicitly) {
  auto s = stiff();
  s.scheme = "serial-explicit";
  const auto dir = scratch_dir("stiff_explicit");
  const auto r = run_scene_text(dir, s.yaml());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const double explicit_amplitude = max_amplitude(read_series(dir / "scene.h5", "/bodies/m1/position"));
  std::cout << "explicit: max |x1| " << explicit_amplitude << " m\n";
  EXPECT_GT(explicit_amplitude, 100 * s.physics.x1);

  s.scheme = "serial-implicit";
  const auto implicit = run_scene(s, "stiff_implicit");
  const double implicit_amplitude = max_amplitude(implicit.position);
  std::cout << "implicit: max |x1| " << implicit_amplitude << " m, max residual " << implicit.max_residual << "\n";
  EXPECT_LT(implicit.max_residual, s.tolerance);
  // Energy is bounded: the first mass never moves further than both springs allow.
  EXPECT_LT(implicit_amplitude, 3 * s.physics.x1);

  // And with a window that resolves the fast mode the implicit answer is accurate.
  s.window = 0.001;
  s.dt_mass = s.dt_spring = 0.0001;
  s.end = 0.2;
  EXPECT_LT(run_scene(s, "stiff_implicit_fine").max_error, 2e-3);
}

TEST(Oscillator, AitkenAndIqnIlsNeedFewerIterationsThanConstantRelaxation) {
  auto s = stiff();
  std::map<std::string, Outcome> by;
  for (const std::string a : {"constant", "aitken", "iqn-ils"}) {
    s.acceleration = a;  // all with the same first relaxation factor, 0.5
    by[a] = run_scene(s, "accel_" + a);
    std::cout << a << ": " << by[a].mean_iterations << " iterations per window, max residual " << by[a].max_residual
              << "\n";
    EXPECT_LT(by[a].max_residual, s.tolerance) << a;
  }
  EXPECT_LT(by["aitken"].mean_iterations, by["constant"].mean_iterations);
  EXPECT_LT(by["iqn-ils"].mean_iterations, by["constant"].mean_iterations);
  // They converge to the same coupled solution.
  EXPECT_LT(std::abs(by["aitken"].max_error - by["constant"].max_error), 1e-6);
  EXPECT_LT(std::abs(by["iqn-ils"].max_error - by["constant"].max_error), 1e-6);
}

// Guards against: coupling.force_tolerance not stopping a window whose forces no longer
// change by more than it (what bodies at rest need, whose forces fade towards round-off).
// On the stiff case under constant relaxation (linear convergence, some 24 iterations per
// window), whose spring force is some 40 N, a force tolerance of 1e-3 N stops windows
// earlier than the relative 1e-8 alone, and the answer moves by far less than the
// scheme's own error.
TEST(Oscillator, ForceToleranceStopsWindowsWhoseForcesNoLongerChange) {
  auto s = stiff();
  s.acceleration = "constant";
  const Outcome tight = run_scene(s, "force_tolerance_off");
  s.force_tolerance = 1e-3;
  const Outcome loose = run_scene(s, "force_tolerance_on");
  std::cout << "force tolerance 0: " << tight.mean_iterations << " iterations per window, error " << tight.max_error
            << "; 1e-3 N: " << loose.mean_iterations << ", error " << loose.max_error << "\n";
  EXPECT_LT(loose.mean_iterations, tight.mean_iterations - 0.5);
  EXPECT_LT(std::abs(loose.max_error - tight.max_error), 0.01 * tight.max_error);
}

TEST(Oscillator, SubcyclingWithDifferentStepsGivesTheSameAnswer) {
  auto s = base();
  s.window = 0.01;
  s.dt_mass = s.dt_spring = 0.00025;
  const auto same = run_scene(s, "subcycle_same");
  s.dt_mass = 0.001;  // 10 substeps against 40
  const auto mixed = run_scene(s, "subcycle_mixed");
  ASSERT_EQ(same.position.rows, mixed.position.rows);
  double diff = 0;
  for (std::size_t i = 0; i < same.position.rows; ++i)
    diff = std::max(diff, std::abs(same.position.at(i, 0) - mixed.position.at(i, 0)));
  std::cout << "subcycling: max difference " << diff << " m, errors " << same.max_error << ", " << mixed.max_error
            << "\n";
  EXPECT_LT(diff, 1e-4);
  EXPECT_LT(mixed.max_error, 2e-4);
}

TEST(Oscillator, TcpTransportGivesTheSameAnswerAsIpc) {
  auto s = base();
  const auto ipc = run_scene(s, "ipc");
  s.transport = "tcp";
  const auto tcp = run_scene(s, "tcp");
  EXPECT_EQ(ipc.position.values, tcp.position.values);
}

}  // namespace
}  // namespace cosim::testing
