// Granular throughput: N equal spheres poured into a box (pour.hpp), run by cosim's
// rigid-body world (soft step, sequential impulses or DEM), by Bullet when built with
// -DCOSIM_BENCH_BULLET=ON, and by LIGGGHTS when its executable is installed, on the same
// scene. Prints body-steps per second of processor time, the memory per body, and the
// pile each leaves: packing, height, deepest overlap, kinetic-energy decay.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include "bench/rigidbody_granular/engines.hpp"

namespace {

using cosim::bench::RunResult;

double rate(const RunResult& r) { return static_cast<double>(r.bodies) * r.steps / r.cpu_seconds; }

double kinetic_peak(const RunResult& r) {
  return r.kinetic_energy.empty() ? 0.0 : *std::max_element(r.kinetic_energy.begin(), r.kinetic_energy.end());
}

// The first time after the peak that the kinetic energy is below 1 % of the peak; NaN if never.
double settling_time(const RunResult& r) {
  const auto peak = std::max_element(r.kinetic_energy.begin(), r.kinetic_energy.end());
  if (peak == r.kinetic_energy.end()) return std::nan("");
  for (auto e = peak; e != r.kinetic_energy.end(); ++e)
    if (*e < 1e-2 * *peak) return static_cast<double>(e - r.kinetic_energy.begin()) * r.kinetic_every * r.dt;
  return std::nan("");
}

void print_header() {
  std::printf("%-8s %7s %6s %7s %8s %8s %12s %8s %8s %7s %6s %10s %8s %9s %8s\n", "engine", "N", "steps", "dt[s]",
              "wall[s]", "cpu[s]", "body-steps/s", "pairs/s", "B/body", "rss/N", "phi", "H/r", "pen./r", "KE end/pk",
              "t1%[s]");
}

void print(const RunResult& r, double radius) {
  std::printf("%-8s %7zu %6d %7.0e %8.2f %8.2f %12.3e %8.2e %8.0f %7.0f %6.4f %10.2f %8.2e %9.2e %8.3f\n",
              r.engine.c_str(), r.bodies, r.steps, r.dt, r.wall_seconds, r.cpu_seconds, rate(r),
              r.pairs_tested / r.cpu_seconds, r.heap_bytes / static_cast<double>(r.bodies),
              r.peak_rss_bytes / static_cast<double>(r.bodies), r.packing_fraction, r.pile_height / radius,
              r.max_penetration / radius,
              r.kinetic_energy.empty() ? std::nan("") : r.kinetic_energy.back() / kinetic_peak(r), settling_time(r));
  std::fflush(stdout);
}

// Throughput per body relative to the smallest N: 1 is linear scaling.
void print_scaling(const std::vector<RunResult>& runs) {
  for (const RunResult& r : runs) {
    const RunResult* base = nullptr;
    for (const RunResult& b : runs)
      if (b.engine == r.engine && (base == nullptr || b.bodies < base->bodies)) base = &b;
    if (base == &r) continue;
    std::printf("%s: body-steps/s at N = %zu is %.2f of that at N = %zu\n", r.engine.c_str(), r.bodies,
                rate(r) / rate(*base), base->bodies);
  }
}

// Each cosim run against a peer's run of the same N and step (Bullet: at least twice its
// rate at no larger overlap; LIGGGHTS: at least twice its rate at the same packing within
// 2 %). Body-steps of different steps do not compare.
void print_ratios(const std::vector<RunResult>& runs, const std::string& peer) {
  for (const RunResult& other : runs) {
    if (other.engine != peer) continue;
    for (const RunResult& r : runs)
      if (r.engine != "bullet" && r.engine != "liggghts" && r.bodies == other.bodies && r.dt == other.dt)
        std::printf("%s / %s at N = %zu: body-steps/s %.2fx, max overlap %.2fx, packing %+.2f %%, memory %.3fx\n",
                    r.engine.c_str(), peer.c_str(), r.bodies, rate(r) / rate(other),
                    r.max_penetration / other.max_penetration, 100 * (r.packing_fraction / other.packing_fraction - 1),
                    r.heap_bytes / other.heap_bytes);
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Poured spheres: cosim's rigid-body world against Bullet and LIGGGHTS"};
  std::vector<std::size_t> sizes{1000, 10000, 100000};
  int steps = 500;
  int iterations = 10;
  std::vector<std::string> solvers{"soft"};
  cosim::bench::CosimRun cosim_run;
  [[maybe_unused]] bool bullet = false;  // only with COSIM_BENCH_BULLET
  bool liggghts = false;
  bool liggghts_failed = false;
  cosim::bench::LiggghtsRun liggghts_run;
  cosim::bench::PourScene defaults;  // the DEM material's and step's defaults
  app.add_option("-n,--bodies", sizes, "numbers of spheres")->capture_default_str();
  app.add_option("--steps", steps, "steps of 1 ms")->capture_default_str()->check(CLI::PositiveNumber);
  app.add_option("--iterations", iterations, "SI's and Bullet's contact-solver iterations per step")
      ->capture_default_str();
  app.add_option("--solver", solvers,
                 "cosim's solvers: soft (the default, its own sweeps), si and/or dem (Hertz-Mindlin, as LIGGGHTS)")
      ->capture_default_str()
      ->check(CLI::IsMember({"soft", "si", "dem"}));
  // What the soft step's overlap in a pile costs to bring down (README.md "The soft step's
  // settings"): more substeps, more sweeps, stiffer springs.
  app.add_option("--substeps", cosim_run.soft.substeps, "the soft step's substeps per 1 ms step and narrow phase")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--sweeps", cosim_run.soft.iterations, "the soft step's sweeps with bias per substep")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--relax", cosim_run.soft.relax_iterations, "the soft step's rigid sweeps per substep")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  app.add_option("--hertz", cosim_run.soft.hertz, "the soft step's contact spring frequency [Hz]")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
#ifdef COSIM_BENCH_BULLET
  app.add_flag("--bullet", bullet, "run Bullet on each scene too");
#endif
  app.add_flag("--liggghts", liggghts, "run LIGGGHTS on each scene too (skipped if not installed)");
  app.add_option("--liggghts-exe", liggghts_run.executable, "LIGGGHTS's executable")->capture_default_str();
  app.add_option("--liggghts-dir", liggghts_run.directory, "keep LIGGGHTS's decks and output here (default: removed)");
  // The DEM engines' material and step (pour.hpp says why these).
  app.add_option("--dem-dt", defaults.dem_dt, "DEM and LIGGGHTS step [s]")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--young", defaults.hertz.young, "DEM and LIGGGHTS Young's modulus [Pa]")->capture_default_str();
  app.add_option("--poisson", defaults.hertz.poisson, "DEM and LIGGGHTS Poisson's ratio")->capture_default_str();
  app.add_option("--restitution", defaults.hertz.restitution, "DEM and LIGGGHTS coefficient of restitution")
      ->capture_default_str()
      ->check(CLI::Range(1e-3, 1.0));
  CLI11_PARSE(app, argc, argv);
  // The world's tunnelling warnings go to stderr, so the table on stdout stays a table.
  spdlog::set_default_logger(spdlog::stderr_color_mt("rigidbody_granular"));

  std::vector<RunResult> runs;
  print_header();
  for (const std::size_t n : sizes) {
    cosim::bench::PourScene scene = cosim::bench::pour(n);
    scene.steps = steps;
    scene.iterations = iterations;
    scene.dem_dt = defaults.dem_dt;
    scene.hertz = defaults.hertz;
    for (const std::string& solver : solvers) {
      cosim_run.solver = solver == "soft"  ? cosim::rigidbody::world::SolverKind::soft
                         : solver == "dem" ? cosim::rigidbody::world::SolverKind::dem
                                           : cosim::rigidbody::world::SolverKind::sequential_impulses;
      runs.push_back(cosim::bench::run_cosim(scene, cosim_run));
      print(runs.back(), scene.radius);
    }
    if (liggghts) {
      // Absent, it is skipped; installed but failing, the other engines' rows still stand
      // and the exit status says it failed.
      std::optional<RunResult> r;
      try {
        r = cosim::bench::run_liggghts(scene, liggghts_run);
      } catch (const std::exception& e) {
        std::printf("# liggghts: failed at N = %zu: %s\n", n, e.what());
        liggghts_failed = true;
      }
      if (r) {
        runs.push_back(*r);
        print(runs.back(), scene.radius);
      } else {
        liggghts = false;  // said why once
      }
    }
#ifdef COSIM_BENCH_BULLET
    if (bullet) {
      runs.push_back(cosim::bench::run_bullet(scene));
      print(runs.back(), scene.radius);
    }
#endif
  }
  print_scaling(runs);
  print_ratios(runs, "bullet");
  print_ratios(runs, "liggghts");
  return liggghts_failed ? 1 : 0;
}
