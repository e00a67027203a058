// A sphere in ten Cate's box, cosim-fluid and cosim-rigidbody coupled through `cosim run`
// (the real programs): the hard cases of partitioned fluid-body coupling, each a few
// seconds. With the staircase on a coarse grid (20 x 20 x 32 cells, d/h = 3) with its
// surface offset off (a/h = 1.5 is below its calibrated range, where it would overstate the
// added mass: the first window's velocity of the light sphere below halves with it); with
// the immersed boundary at d/h = 6 (40 x 40 x 64 cells).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <thread>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "tests/integration/cosim_process.hpp"
#include "tests/integration/h5_read.hpp"

namespace cosim::testing {
namespace {

constexpr double kG = 9.81;
constexpr double kRadius = 0.0075;

struct Settling {
  double rho_p = 1120, rho_f = 960, mu = 0.058;
  double z0 = 0.1275;
  double w0 = 0;  // initial vertical velocity
  std::string scheme = "serial-implicit";
  double window = 0.005;
  double end = 0.05;
  int checkpoint_every = 1000;
  double virtual_mass = 0;
  std::string lubrication = {};  // the rigid body's film options, none if empty
  std::string bodies = "{method: staircase, surface_offset: 0}";
  std::string cells = "[20, 20, 32]";

  std::string yaml() const {
    const bool implicit = scheme.ends_with("implicit");
    return "time: {end: " + std::to_string(end) + "}\n" + "coupling: {window: " + std::to_string(window) +
           ", scheme: " + scheme +
           (implicit ? ", acceleration: iqn-ils, relaxation: 0.5, max_iterations: 30, tolerance: 1.0e-4" : "") + "}\n" +
           "output: {checkpoint_every: " + std::to_string(checkpoint_every) + ", fields_every: 0}\n" +
           "gravity: [0, 0, -9.81]\n"
           "domain: {min: [0, 0, 0], max: [0.1, 0.1, 0.16]}\n"
           "effects: [gravity, buoyancy, hydrodynamics, contact]\n"
           "bodies:\n"
           "  - {name: sphere, shape: {type: sphere, radius: 0.0075}, material: {density: " +
           std::to_string(rho_p) + "}, position: [0.05, 0.05, " + std::to_string(z0) + "], velocity: [0, 0, " +
           std::to_string(w0) +
           "]}\n"
           "participants:\n"
           "  rigidbody: {dt: " +
           std::to_string(std::min(window / 10, 5e-4)) + ", options: {fluid_density: " + std::to_string(rho_f) +
           ", virtual_mass: " + std::to_string(virtual_mass) + ", walls: [z_min, z_max]" +
           (lubrication.empty() ? "" : ", lubrication: " + lubrication) +
           "}}\n"
           "  fluid:\n"
           "    dt: " +
           std::to_string(window) +
           "\n"
           "    options: {density: " +
           std::to_string(rho_f) + ", viscosity: {model: newtonian, mu: " + std::to_string(mu) +
           "}, grid: {cells: " + cells + "}, dt_initial: " + std::to_string(window) + ", bodies: " + bodies + "}\n";
  }
};

struct Motion {
  Series z, w, iterations, residual;
};

Motion run(const std::string& name, const Settling& s) {
  const auto dir = scratch_dir(name);
  const Finished f = run_scene_text(dir, s.yaml());
  EXPECT_EQ(f.exit_code, 0) << f.output;
  const auto file = dir / "scene.h5";
  Motion r;
  const Series position = read_series(file, "/bodies/sphere/position");
  const Series velocity = read_series(file, "/bodies/sphere/velocity");
  for (std::size_t k = 0; k < position.rows; ++k) {
    r.z.values.push_back(position.at(k, 2));
    r.w.values.push_back(velocity.at(k, 2));
  }
  r.z.rows = r.w.rows = position.rows;
  r.iterations = read_series(file, "/coupling/iterations");
  r.residual = read_series(file, "/coupling/residual");
  return r;
}

// Guards against: the added-mass instability of partitioned coupling going unnoticed. A
// sphere at 0.3 times the fluid's density: serial-explicit takes each window's force from
// the previous one, so the added mass (rho_f V / 2, 1.7 times the sphere's mass) turns the
// velocity over every window with a growing amplitude; serial-implicit with IQN-ILS
// converges every window in a few iterations and the sphere rises smoothly. So does
// serial-explicit with a virtual mass of rho_f V (one run of each program per window).
TEST(Settling, ALightSphereDivergesExplicitlyAndConvergesImplicitly) {
  Settling s{.rho_p = 291, .rho_f = 970, .mu = 0.373, .z0 = 0.05};
  const Motion implicit = run("settling_light_implicit", s);
  s.scheme = "serial-explicit";
  const Motion explicit_ = run("settling_light_explicit", s);
  s.virtual_mass = 1;
  const Motion stabilized = run("settling_light_virtual_mass", s);
  ASSERT_EQ(implicit.w.rows, 11u);
  ASSERT_EQ(explicit_.w.rows, 11u);
  ASSERT_EQ(stabilized.w.rows, 11u);
  for (std::size_t k = 1; k < implicit.w.rows; ++k) {
    EXPECT_LE(implicit.iterations.at(k), 6) << "window " << k;
    EXPECT_LT(implicit.residual.at(k), 1e-4) << "window " << k;
  }
  // A turn of the acceleration; the implicit run has one where a face switches between
  // fluid and solid (the staircase FBM at d/h = 3), the explicit one every window.
  const auto turns = [](const Series& w) {
    int n = 0;
    for (std::size_t k = 2; k < w.rows; ++k)
      if ((w.at(k) - w.at(k - 1)) * (w.at(k - 1) - w.at(k - 2)) < 0) ++n;
    return n;
  };
  std::printf(
      "rho_p/rho_f 0.3: w after 50 ms implicit %.4f m/s, explicit %.4f m/s, explicit with virtual mass "
      "%.4f m/s; turns %d, %d and %d\n",
      implicit.w.at(10), explicit_.w.at(10), stabilized.w.at(10), turns(implicit.w), turns(explicit_.w),
      turns(stabilized.w));
  EXPECT_LE(turns(implicit.w), 3);
  EXPECT_GT(implicit.w.at(10), 0.1);
  EXPECT_GE(turns(explicit_.w), 8);
  EXPECT_GT(std::abs(explicit_.w.at(10)), 3 * implicit.w.at(10));
  EXPECT_LE(turns(stabilized.w), 3);
  EXPECT_NEAR(stabilized.w.at(10), implicit.w.at(10), 0.1 * implicit.w.at(10));
}

// Guards against: a body almost as dense as the fluid (the implicit scheme's hardest case:
// the fluid's reaction nearly cancels the body's own inertia). At rho_p/rho_f = 1.01 the
// sphere starts with a0 = (rho_p - rho_f) g / (rho_p + rho_f / 2), the added-mass value;
// drag and the history force only slow it, so after 20 ms it has at most a0 t and, on this
// grid, at least 80 % of it.
// A sphere at rho_p/rho_f = 1.01 released at rest for 20 ms under serial-implicit coupling:
// every window converges in a few iterations; returns w(20 ms) over the added-mass a0 t.
double ratio_at_101(const std::string& name, Settling s) {
  s.rho_p = 969.6;
  s.end = 0.02;
  const Motion r = run(name, s);
  EXPECT_EQ(r.w.rows, 5u);
  if (r.w.rows < 5) return std::nan("");
  for (std::size_t k = 1; k < r.w.rows; ++k) {
    EXPECT_LE(r.iterations.at(k), 8) << "window " << k;
    EXPECT_LT(r.residual.at(k), 1e-4) << "window " << k;
  }
  const double a0 = (s.rho_p - s.rho_f) * kG / (s.rho_p + s.rho_f / 2);
  const double ratio = -r.w.at(4) / (a0 * 0.02);
  std::printf("%s, rho_p/rho_f 1.01: w(20 ms) = %.4g m/s, %.3f of the added-mass a0 t\n", s.bodies.c_str(), r.w.at(4),
              ratio);
  return ratio;
}

TEST(Settling, DensityRatioOnePointZeroOneConvergesWithTheAddedMassAcceleration) {
  const double ratio = ratio_at_101("settling_ratio_101", Settling{});
  EXPECT_GT(ratio, 0.8);
  EXPECT_LE(ratio, 1.0);
}

const Settling kImmersed{.bodies = "{method: ibm}", .cells = "[40, 40, 64]"};

// Guards against: the added-mass instability with the immersed boundary, whose load holds
// the inside fluid's momentum change (its inertia, rho_f V, taken from the flow). The light
// sphere (rho_p/rho_f 0.3) under serial-implicit IQN-ILS: every window converges in a few
// iterations and the sphere rises without a turn of its acceleration, slower than the
// added-mass acceleration alone would take it (0.43 m/s in 50 ms): drag and the history
// force hold it back (its Stokes relaxation time is 26 ms).
TEST(Settling, ImmersedBoundaryLightSphereConvergesImplicitly) {
  Settling s = kImmersed;
  s.rho_p = 291;
  s.rho_f = 970;
  s.mu = 0.373;
  s.z0 = 0.05;
  const Motion r = run("settling_ibm_light", s);
  ASSERT_EQ(r.w.rows, 11u);
  int turns = 0;
  for (std::size_t k = 1; k < r.w.rows; ++k) {
    EXPECT_LE(r.iterations.at(k), 8) << "window " << k;
    EXPECT_LT(r.residual.at(k), 1e-4) << "window " << k;
    if (k >= 2 && (r.w.at(k) - r.w.at(k - 1)) * (r.w.at(k - 1) - r.w.at(k - 2)) < 0) ++turns;
  }
  std::printf("immersed boundary, rho_p/rho_f 0.3: w after 50 ms %.4f m/s, %d turns\n", r.w.at(10), turns);
  EXPECT_GT(r.w.at(10), 0.05);
  EXPECT_LT(r.w.at(10), 0.43);
  EXPECT_EQ(turns, 0);
}

// Guards against: the immersed boundary at rho_p/rho_f = 1.01, where the inside fluid's
// momentum nearly cancels the body's inertia: the sphere starts with the added-mass
// acceleration a0 = (rho_p - rho_f) g / (rho_p + rho_f / 2), and the Basset history force
// 6 a^2 sqrt(pi rho_f mu) int du/dtau / sqrt(t - tau) dtau, resolved at d/h = 6 as it is not
// at 3, holds it to about 1 - (4/3) (B / m) sqrt(t) = 0.67 of a0 t at 20 ms (B = 6 a^2
// sqrt(pi rho_f mu), m = (rho_p + rho_f / 2) V; the expansion's first term); every window
// converges in a few iterations.
TEST(Settling, ImmersedBoundaryDensityRatioOnePointZeroOne) {
  const double ratio = ratio_at_101("settling_ibm_ratio_101", kImmersed);
  EXPECT_GT(ratio, 0.5);
  EXPECT_LT(ratio, 0.85);
}

// Guards against: a body touching a wall at t = 0 (its FBM cells reach the boundary faces,
// the contact starts at zero gap). The sphere sits on the floor: it neither sinks into it
// nor jumps off, and every window converges.
TEST(Settling, ASphereRestingOnTheFloorAtTheStartStaysThere) {
  const Settling s{.z0 = kRadius, .end = 0.1};
  const Motion r = run("settling_on_floor", s);
  ASSERT_EQ(r.z.rows, 21u);
  double lowest = r.z.at(0), fastest = 0;
  for (std::size_t k = 1; k < r.z.rows; ++k) {
    EXPECT_LE(r.iterations.at(k), 6) << "window " << k;
    lowest = std::min(lowest, r.z.at(k));
    fastest = std::max(fastest, std::abs(r.w.at(k)));
  }
  std::printf("sphere on the floor: lowest z - r = %.3g m, fastest |w| %.3g m/s\n", lowest - kRadius, fastest);
  EXPECT_GT(lowest, kRadius * 0.99);
  EXPECT_LT(r.z.at(20), kRadius * 1.01);
  EXPECT_LT(fastest, 1e-3);
}

// Guards against: a landing through cosim-rigidbody's lubrication film (its implicit
// normal damping, which grows like 1/gap, against the coupled fluid force) losing the
// implicit scheme's convergence or bouncing the sphere. Launched at 0.2 m/s 4 mm above the
// floor (d/h 4.5), the sphere still moves at 0.12 m/s after the first window. The window of an impulsive
// landing stalls at max_iterations only when the contact falls so within it that IQN-ILS's
// iterates straddle the kink (ten Cate's quick scene: 30 iterations, residual 0.27; with
// the film 9, docs/results.md); this drop converges without the film too.
TEST(Settling, ASphereLandingThroughTheFilmConvergesEveryWindow) {
  Settling s = kImmersed;
  s.cells = "[30, 30, 48]";
  s.z0 = kRadius + 0.004;
  s.w0 = -0.2;
  s.end = 0.1;
  s.lubrication = "{viscosity: 0.058, range: 3.3e-3}";
  const Motion r = run("settling_landing", s);
  const std::size_t last = r.z.rows - 1;
  double fastest = 0, rising = 0, most = 0;
  for (std::size_t k = 1; k < r.z.rows; ++k) {
    EXPECT_LE(r.iterations.at(k), 12) << "window " << k;
    most = std::max(most, r.iterations.at(k));
    EXPECT_LT(r.residual.at(k), 1e-4) << "window " << k;
    fastest = std::max(fastest, -r.w.at(k));
    rising = std::max(rising, r.w.at(k));
  }
  std::printf("landing: fastest %.4f m/s, gap at the end %.3g m, fastest rise %.3g m/s, at most %g iterations\n",
              fastest, r.z.at(last) - kRadius, rising, most);
  EXPECT_GT(fastest, 0.08);
  EXPECT_LT(r.z.at(last) - kRadius, 1e-4);
  EXPECT_LT(rising, 1e-3);
}

// Guards against: losing the implicit scheme's convergence at long windows, where the
// fluid subcycles (35 steps in the first window) and the body's velocity changes most in a
// window. At 50 ms, ten times the scene's window, every window converges in a few
// iterations and the velocity at 0.2 s is within 8 % of the 5 ms run's: the staircase's
// jumps at d/h = 3 land at other instants with other windows, which moved it by 4.5, 3.0
// and 5.8 % at 10, 20 and 50 ms. At 100 ms the second window no longer converges (30
// iterations, residual 0.02: measured, not tested).
TEST(Settling, FiftyMillisecondWindowsStillConverge) {
  Settling s{.end = 0.2};
  const Motion fine = run("settling_window_5ms", s);
  s.window = 0.05;
  const Motion coarse = run("settling_window_50ms", s);
  ASSERT_EQ(coarse.w.rows, 5u);
  for (std::size_t k = 1; k < coarse.w.rows; ++k) {
    EXPECT_LE(coarse.iterations.at(k), 6) << "window " << k;
    EXPECT_LT(coarse.residual.at(k), 1e-4) << "window " << k;
  }
  std::printf("w(0.2 s): windows of 5 ms %.4f m/s, of 50 ms %.4f m/s\n", fine.w.at(40), coarse.w.at(4));
  EXPECT_NEAR(coarse.w.at(4), fine.w.at(40), 0.08 * std::abs(fine.w.at(40)));
}

// Guards against: beads packed on the floor blowing up under explicit coupling. The shipped
// fluidized bed starts with 112 beads in a lattice on its floor, 0.25 mm from the side walls;
// under plain serial-explicit coupling the beads reached 0.43 m/s in 10 ms on the staircase.
// Its first 5 windows run, under the scene's own coupling (serial-explicit, the immersed
// boundary with its response tensors).
TEST(Settling, TheFluidizedBedsLatticeOfBeadsStartsStably) {
  std::ifstream in(std::string(COSIM_CONFIGS_DIR) + "/fluidized-bed.yaml");
  std::stringstream text;
  text << in.rdbuf();
  std::string yaml = text.str();
  const auto at = yaml.find("  end: 2.0");
  ASSERT_NE(at, std::string::npos);
  yaml.replace(at, 10, "  end: 0.01");
  const auto dir = scratch_dir("settling_fluidized_bed");
  const Finished f = run_scene_text(dir, yaml);
  ASSERT_EQ(f.exit_code, 0) << f.output;
  EXPECT_EQ(read_series(dir / "scene.h5", "/coupling/time").rows, 2u);  // every 5th window, and the start
  // Stable: they move slower than the inflow (0.12 m/s).
  double fastest = 0;
  for (int b = 0; b < 112; ++b) {
    char name[8];
    std::snprintf(name, sizeof name, "b%03d", b);
    const Series v = read_series(dir / "scene.h5", std::string("/bodies/") + name + "/velocity");
    for (std::size_t k = 0; k < v.rows; ++k)
      fastest = std::max(fastest, std::hypot(v.at(k, 0), v.at(k, 1), v.at(k, 2)));
  }
  std::printf("fluidized bed, first 10 ms: fastest bead %.4f m/s\n", fastest);
  EXPECT_LT(fastest, 0.12);
}

// 16 spheres of the sedimenting bed (r 0.0125, rho_p/rho_f 1.2, nu 1e-3) on the floor of a
// 0.15 x 0.15 x 0.1 box, 0.026 apart (a 1 mm gap) and off the grid's symmetry by a
// different fraction each, their centres at z; serial-explicit with 20 ms windows.
struct FloorLayer {
  double z = 0.0126;  // 0.1 mm above the floor
  double end = 1.0;
  double virtual_mass = 0;
  std::string solver = "solver: sequential-impulses, ";
  std::string fluid = "grid: {cells: [12, 12, 8]}, bodies: {method: staircase, surface_offset: 0}";  // d/h 2

  std::string yaml() const {
    std::string bodies;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        const double x = 0.0375 + 0.026 * i + 1e-4 * j, y = 0.0375 + 0.026 * j - 1e-4 * i;
        bodies += "  - {name: s" + std::to_string(4 * i + j) +
                  ", shape: {type: sphere, radius: 0.0125}, material: {density: 1.2, friction: 0.3}, position: [" +
                  std::to_string(x) + ", " + std::to_string(y) + ", " + std::to_string(z) + "]}\n";
      }
    return "time: {end: " + std::to_string(end) +
           "}\n"
           "coupling: {window: 0.02, scheme: serial-explicit}\n"
           "output: {checkpoint_every: 1000, fields_every: 0}\n"
           "gravity: [0, 0, -9.81]\n"
           "domain: {min: [0, 0, 0], max: [0.15, 0.15, 0.1]}\n"
           "effects: [gravity, buoyancy, hydrodynamics, contact, friction]\n"
           "bodies:\n" +
           bodies +
           "participants:\n"
           "  rigidbody: {dt: 1.0e-3, options: {" +
           solver + "fluid_density: 1.0, virtual_mass: " + std::to_string(virtual_mass) +
           ", walls: [x_min, x_max, y_min, y_max, z_min, z_max]}}\n"
           "  fluid:\n"
           "    dt: 0.02\n"
           "    options: {density: 1.0, viscosity: {model: newtonian, mu: 1.0e-3}, dt_initial: 0.02, " +
           fluid + "}\n";
  }
};

struct LayerRun {
  double fastest = 0;  // m/s, over the windows from `since`
  double overlap = 0;  // the deepest of any two spheres or a sphere and the floor, of the radius
  double height = 0;   // mean z at the end
};

LayerRun run_layer(const std::string& name, const FloorLayer& layer, double since) {
  constexpr double r = 0.0125;
  const auto dir = scratch_dir(name);
  const Finished f = run_scene_text(dir, layer.yaml());
  EXPECT_EQ(f.exit_code, 0) << f.output;
  const auto file = dir / "scene.h5";
  const Series time = read_series(file, "/coupling/time");
  LayerRun out;
  std::vector<Series> positions;
  for (int b = 0; b < 16; ++b) {
    const Series v = read_series(file, "/bodies/s" + std::to_string(b) + "/velocity");
    for (std::size_t k = 0; k < v.rows; ++k)
      if (time.at(k) >= since - 1e-12)
        out.fastest = std::max(out.fastest, std::hypot(v.at(k, 0), v.at(k, 1), v.at(k, 2)));
    positions.push_back(read_series(file, "/bodies/s" + std::to_string(b) + "/position"));
  }
  for (std::size_t k = 0; k < time.rows; ++k)
    for (int a = 0; a < 16; ++a) {
      out.overlap = std::max(out.overlap, (r - positions[a].at(k, 2)) / r);
      for (int b = a + 1; b < 16; ++b) {
        const double d =
            std::hypot(positions[a].at(k, 0) - positions[b].at(k, 0), positions[a].at(k, 1) - positions[b].at(k, 1),
                       positions[a].at(k, 2) - positions[b].at(k, 2));
        out.overlap = std::max(out.overlap, (2 * r - d) / r);
      }
    }
  for (const Series& p : positions) out.height += p.at(p.rows - 1, 2) / 16;
  return out;
}

// Guards against: bodies packed on a floor blowing up under explicit coupling. A sphere
// resting on the floor among others, two cells across, meets a fluid force against its
// sideways velocity some 13 times Stokes' (the fluid squeezed through one-cell gaps): with
// the force a window late, the sedimenting bed's spheres rocked sideways with a growing
// amplitude once they landed (1 m/s within 0.4 s). A virtual mass of 4 rho_f V
// (cosim-rigidbody's virtual_mass) keeps the layer at rest, as it keeps the whole bed.
// Measured with sequential impulses, named here: under the soft step the unstabilized run
// did not end within the 60 s the test allows (not yet measured why).
TEST(Settling, SpheresRestingOnTheFloorStayAtRestWithAVirtualMass) {
  const double plain = run_layer("settling_floor_plain", {.end = 0.8}, 0.2).fastest;
  const double stabilized = run_layer("settling_floor_virtual_mass", {.virtual_mass = 4}, 0.2).fastest;
  std::printf(
      "16 spheres on the floor, explicit: fastest %.4f m/s from 0.2 to 0.8 s; with virtual mass 4: %.6f m/s "
      "from 0.2 to 1 s\n",
      plain, stabilized);
  EXPECT_GT(plain, 0.5);
  EXPECT_LT(stabilized, 1e-3);
}

// The immersed boundary at d/h 6 under the default soft step, with the lubrication film of
// the fluid's viscosity below the gap its grid resolves (`lubrication: auto`) between every
// pair and wall: the fluid sends
// its response tensors (fluid/window_response.hpp) and the layer needs no virtual mass.
FloorLayer immersed_layer(double z, double end) {
  return {.z = z,
          .end = end,
          .solver = "lubrication: auto, ",
          .fluid = "grid: {cells: [36, 36, 24]}, bodies: {method: ibm}"};
}

// Guards against: a packed layer under explicit coupling moving by itself. The 16 spheres
// start resting on the floor and stay there for 2 s, slower than 1e-4 m/s throughout.
TEST(Settling, ImmersedSpheresRestingOnTheFloorStayAtRestExplicitly) {
  const LayerRun r = run_layer("settling_floor_immersed", immersed_layer(0.0125, 2.0), 0.0);
  std::printf("16 spheres resting on the floor, immersed boundary, explicit: fastest %.3g m/s over 2 s\n", r.fastest);
  EXPECT_LT(r.fastest, 1e-4);
  EXPECT_LT(r.overlap, 0.01);
}

// Guards against: a bed landing under explicit coupling bouncing or sinking into the floor
// and into itself. The same 16 spheres fall from 37.5 mm above the floor at about 0.02 m/s
// and reach the floor's cell by 2.4 s: no sphere overlaps another or the floor by 1 % of its
// radius, and by 4 s the layer lies on the floor, its fastest sphere below 2e-4 m/s (a
// hundredth of the fall's speed; the film below it drains on, the speed halving every
// 0.2 s).
TEST(Settling, AnImmersedLayerFallsOntoTheFloorWithoutOverlap) {
  const LayerRun r = run_layer("settling_fall_immersed", immersed_layer(0.05, 4.0), 4.0);
  std::printf(
      "16 spheres falling onto the floor, immersed boundary, explicit: deepest overlap %.3g %% of the radius, "
      "mean height %.5f m, fastest at 4 s %.3g m/s\n",
      100 * r.overlap, r.height, r.fastest);
  EXPECT_LT(r.overlap, 0.01);
  EXPECT_NEAR(r.height, 0.0125, 2e-5);
  EXPECT_LT(r.fastest, 2e-4);
}

// Guards against: explicit coupling of a light or neutrally buoyant body losing accuracy to
// the load's lag. The immersed sphere at d/h 6 in ten Cate's heavier oil (mu 0.373), at
// rho_p/rho_f 0.5 and 1.01: under serial-explicit coupling, with the fluid's response
// tensors, its velocity stays within 1 % of the serial-implicit run's at every window for
// 0.1 s (two Stokes times at 0.5), with no virtual mass; the implicit run takes at most 4
// iterations a window.
TEST(Settling, ImmersedBoundaryExplicitFollowsImplicit) {
  for (const double ratio : {0.5, 1.01}) {
    Settling s = kImmersed;
    s.rho_f = 970;
    s.mu = 0.373;
    s.rho_p = ratio * s.rho_f;
    s.z0 = 0.08;
    s.end = 0.1;
    const std::string tag = ratio < 1 ? "05" : "101";
    const Motion implicit = run("settling_ibm_implicit_" + tag, s);
    s.scheme = "serial-explicit";
    const Motion explicit_ = run("settling_ibm_explicit_" + tag, s);
    ASSERT_EQ(explicit_.w.rows, 21u);
    ASSERT_EQ(implicit.w.rows, 21u);
    double worst = 0, iterations = 0;
    for (std::size_t k = 1; k < implicit.w.rows; ++k) {
      worst = std::max(worst, std::abs(explicit_.w.at(k) - implicit.w.at(k)) / std::abs(implicit.w.at(k)));
      iterations = std::max(iterations, implicit.iterations.at(k));
      EXPECT_LT(implicit.residual.at(k), 1e-4) << "window " << k;
    }
    std::printf(
        "immersed sphere at rho_p/rho_f %.2f: w(0.1 s) explicit %.5f, implicit %.5f m/s; explicit off by at "
        "most %.2f %%; implicit at most %g iterations\n",
        ratio, explicit_.w.at(20), implicit.w.at(20), 100 * worst, iterations);
    EXPECT_LT(worst, 0.01) << "rho_p/rho_f " << ratio;
    EXPECT_LE(iterations, 4) << "rho_p/rho_f " << ratio;
  }
}

// A run of s killed from outside after window 8 (the last checkpoint is at window 5), then
// resumed; checks it ends bit for bit where the whole run ends.
void expect_killed_run_resumed_to_the_same_end(const std::string& name, const Settling& s) {
  const auto dir = scratch_dir(name);
  const Finished whole = run_scene_text(dir, s.yaml(), "whole");
  ASSERT_EQ(whole.exit_code, 0) << whole.output;

  write_file(dir / "killed.yaml", s.yaml());
  CosimProcess cosim(run_args(dir, "killed"));
  const auto file = dir / "killed.h5";
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(50);
  // Twice the same count in a row: a read caught between two flushes can be wrong.
  std::size_t rows = 0, previous = 0;
  while (!(rows >= 9 && rows == previous) && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    previous = rows;
    try {
      rows = read_series(file, "/coupling/time").rows;
    } catch (const std::exception&) {  // not created yet, or caught between two flushes
      rows = 0;
    }
  }
  ASSERT_GE(rows, 9u) << "window 8 not committed in 50 s";
  const pid_t fluid = child_pid(cosim.pid(), "cosim-fluid");
  ASSERT_GT(fluid, 0) << rows << " rows; " << cosim.wait().output;
  kill(fluid, SIGKILL);
  const Finished died = cosim.wait();
  EXPECT_EQ(died.exit_code, 1);
  EXPECT_NE(died.output.find("participant 'fluid' killed by signal 9"), std::string::npos) << died.output;

  const Finished resumed = run_cosim({"run", "--resume", file.string(), "-q"});
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  for (const std::string series : {"/bodies/sphere/position", "/bodies/sphere/velocity", "/bodies/sphere/force"})
    EXPECT_EQ(read_series(file, series).values, read_series(dir / "whole.h5", series).values) << series;
}

// Guards against: a participant dying in a coupled fluid run costing the run, or a resume
// that does not repeat it (the fluid's gathered state, the rigid bodies' contact memory,
// the quasi-Newton history).
TEST(Settling, AFluidKilledMidRunIsResumedToTheSameEnd) {
  expect_killed_run_resumed_to_the_same_end("settling_kill", {.end = 0.2, .checkpoint_every = 5});
}

// The same with the immersed boundary under serial-explicit coupling: the checkpoint holds
// the fluid's response tensors with its forces, and the fluid's state the changes of the
// motion its response kernel still remembers.
TEST(Settling, AnImmersedRunKilledMidRunIsResumedToTheSameEnd) {
  Settling s = kImmersed;
  s.scheme = "serial-explicit";
  s.end = 0.1;
  s.checkpoint_every = 5;
  expect_killed_run_resumed_to_the_same_end("settling_kill_immersed", s);
}

}  // namespace
}  // namespace cosim::testing
