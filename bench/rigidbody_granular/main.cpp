// Granular throughput: N equal spheres poured into a box (pour.hpp), run by cosim's
// rigid-body world and, when built with -DCOSIM_BENCH_BULLET=ON, by Bullet on the same
// scene. Prints body-steps and pair tests per second of processor time, how they scale
// with N, the heap held per body and the deepest overlap at the end.
#include <cstdio>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include "bench/rigidbody_granular/engines.hpp"

namespace {

using cosim::bench::RunResult;

double rate(const RunResult& r) { return static_cast<double>(r.bodies) * r.steps / r.cpu_seconds; }

void print_header() {
  std::printf("%-7s %8s %6s %9s %9s %13s %13s %11s %11s %12s %11s\n", "engine", "N", "steps", "wall[s]", "cpu[s]",
              "body-steps/s", "pairs/s", "heap B/body", "rss B/body", "max pen./r", "mean z/r");
}

void print(const RunResult& r, double radius) {
  std::printf("%-7s %8zu %6d %9.2f %9.2f %13.3e %13.3e %11.0f %11.0f %12.2e %11.2f\n", r.engine.c_str(), r.bodies,
              r.steps, r.wall_seconds, r.cpu_seconds, rate(r), r.pairs_tested / r.cpu_seconds,
              r.heap_bytes / static_cast<double>(r.bodies), r.peak_rss_bytes / static_cast<double>(r.bodies),
              r.max_penetration / radius, r.mean_height / radius);
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

// Each cosim run against Bullet's run of the same N: the goal is at least twice its rate at
// no larger overlap.
void print_ratios(const std::vector<RunResult>& runs) {
  for (const RunResult& bullet : runs) {
    if (bullet.engine != "bullet") continue;
    for (const RunResult& r : runs)
      if (r.engine != "bullet" && r.bodies == bullet.bodies)
        std::printf("%s / bullet at N = %zu: body-steps/s %.2fx, max overlap %.2fx, heap %.3fx\n", r.engine.c_str(),
                    r.bodies, rate(r) / rate(bullet), r.max_penetration / bullet.max_penetration,
                    r.heap_bytes / bullet.heap_bytes);
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Poured spheres: cosim's rigid-body world against Bullet"};
  std::vector<std::size_t> sizes{1000, 10000, 100000};
  int steps = 500;
  int iterations = 10;
  std::vector<std::string> solvers{"soft"};
  cosim::bench::CosimRun cosim_run;
  [[maybe_unused]] bool bullet = false;  // only with COSIM_BENCH_BULLET
  app.add_option("-n,--bodies", sizes, "numbers of spheres")->capture_default_str();
  app.add_option("--steps", steps, "steps of 1 ms")->capture_default_str()->check(CLI::PositiveNumber);
  app.add_option("--iterations", iterations, "SI's and Bullet's contact-solver iterations per step")
      ->capture_default_str();
  app.add_option("--solver", solvers, "cosim's solvers: soft (the default, its own sweeps) and/or si")
      ->capture_default_str()
      ->check(CLI::IsMember({"soft", "si"}));
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
  CLI11_PARSE(app, argc, argv);
  // The world's tunnelling warnings go to stderr, so the table on stdout stays a table.
  spdlog::set_default_logger(spdlog::stderr_color_mt("rigidbody_granular"));

  std::vector<RunResult> runs;
  print_header();
  for (const std::size_t n : sizes) {
    cosim::bench::PourScene scene = cosim::bench::pour(n);
    scene.steps = steps;
    scene.iterations = iterations;
    for (const std::string& solver : solvers) {
      cosim_run.solver = solver == "soft" ? cosim::world::SolverKind::soft : cosim::world::SolverKind::sequential_impulses;
      runs.push_back(cosim::bench::run_cosim(scene, cosim_run));
      print(runs.back(), scene.radius);
    }
#ifdef COSIM_BENCH_BULLET
    if (bullet) {
      runs.push_back(cosim::bench::run_bullet(scene));
      print(runs.back(), scene.radius);
    }
#endif
  }
  print_scaling(runs);
  print_ratios(runs);
  return 0;
}
