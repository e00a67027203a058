// dsmc_study: the DSMC viscosity error in near-continuum Couette flow (hard-sphere argon,
// Kn = 0.05, tests/tracker/transport/channel.hpp) against particles per cell, cell size and
// time step, with the wall time of each run, next to the Green-Kubo predictions of the
// cell-size error (Alexander, Garcia & Alder 1998) and the time-step error (Hadjiconstantinou
// 2000). Prints a table; --csv writes it (plot.py draws error against wall time). --quick:
// three short runs (the reference, dx = lambda, dt = tau), for ctest; fails if a particle is
// lost or a viscosity is off its prediction by more than 4 sigma + 5 %. --sweep ppc|cell|dt:
// only that sweep of the full study (with --quick: its runs, with the short batches).
#include "tests/tracker/transport/channel.hpp"

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

using namespace cosim::tracker::transport;

namespace {

constexpr double kKnudsen = 0.05, kWallSpeed = 300.0;

struct Run {
  std::string sweep;  // which parameter the row varies
  ChannelSpec spec;
  ChannelResult result;
  int steps() const { return spec.warm_up_steps + spec.batches * spec.batch_steps; }
  double cell_over_lambda() const { return 1.0 / (kKnudsen * spec.cells); }
  // The plates' shear against mu U / (H + 2 zeta) with Chapman-Enskog's mu.
  double shear_error() const {
    const double mu = spec.gas.viscosity(result.bulk_temperature);
    return 0.5 * (result.lower_shear.mean + result.upper_shear.mean) /
               slip_shear(mu, kWallSpeed, result.width, result.mean_free_path) -
           1.0;
  }
};

// Every run simulates the same time: 100 mean collision times of warm-up and 20 batches of
// `batch_times` each.
Run run(const std::string& sweep, double ppc, double cell_over_lambda, double dt_over_tau, double batch_times) {
  ChannelSpec s;
  s.knudsen = kKnudsen;
  s.wall_speed = kWallSpeed;
  s.cells = static_cast<int>(std::lround(1.0 / (kKnudsen * cell_over_lambda)));
  s.particles_per_cell = ppc;
  s.dt_over_collision_time = dt_over_tau;
  s.warm_up_steps = static_cast<int>(std::lround(100.0 / dt_over_tau));
  s.batch_steps = static_cast<int>(std::lround(batch_times / dt_over_tau));
  return {sweep, s, run_channel(s)};
}

void print_header() {
  std::printf("%-5s %4s %6s %7s %9s %7s %8s %7s %17s %9s %17s\n", "sweep", "ppc", "dx/lam", "cdt/lam", "particles",
              "steps", "wall [s]", "CPU [s]", "mu/mu_CE - 1", "predicted", "tau/tau_slip - 1");
}

void print_row(const Run& r) {
  const Estimate& v = r.result.viscosity_ratio;
  const double shear_sigma = 0.5 * std::hypot(r.result.lower_shear.error, r.result.upper_shear.error) /
                             (0.5 * (r.result.lower_shear.mean + r.result.upper_shear.mean));
  std::printf("%-5s %4.0f %6.3f %7.3f %9zu %7d %8.2f %7.2f %+7.2f%% +- %4.2f%% %+8.2f%% %+7.2f%% +- %4.2f%%\n",
              r.sweep.c_str(), r.spec.particles_per_cell, r.cell_over_lambda(), r.spec.dt_over_collision_time,
              r.result.particles, r.steps(), r.result.wall_seconds, r.result.cpu_seconds, 100 * (v.mean - 1),
              100 * v.error, 100 * viscosity_error(r.spec), 100 * r.shear_error(), 100 * shear_sigma);
  std::fflush(stdout);
}

void write_csv(const std::string& path, const std::vector<Run>& runs) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path);
  out << "sweep,particles_per_cell,cell_over_lambda,dt_over_collision_time,particles,steps,wall_seconds,cpu_seconds,"
         "error,error_sigma,predicted,shear_error\n";
  for (const Run& r : runs)
    out << r.sweep << ',' << r.spec.particles_per_cell << ',' << r.cell_over_lambda() << ','
        << r.spec.dt_over_collision_time << ',' << r.result.particles << ',' << r.steps() << ','
        << r.result.wall_seconds << ',' << r.result.cpu_seconds << ',' << r.result.viscosity_ratio.mean - 1 << ','
        << r.result.viscosity_ratio.error << ',' << viscosity_error(r.spec) << ',' << r.shear_error() << '\n';
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"DSMC viscosity error in Couette flow against particles per cell, cell size and time step"};
  bool quick = false;
  std::string csv, sweep;
  app.add_flag("--quick", quick, "three short runs (ctest)");
  app.add_option("--csv", csv, "write the table as CSV");
  app.add_option("--sweep", sweep,
                 "only this sweep of the full study (with --quick: its runs with the quick batches; scripts/study)")
      ->check(CLI::IsMember({"ppc", "cell", "dt"}));
  CLI11_PARSE(app, argc, argv);

  struct Case {
    const char* sweep;
    double ppc, cell, dt;
  };
  // Reference: 20 particles per cell, dx = lambda / 3, dt = tau / 4; each sweep varies one.
  const std::vector<Case> all =
      quick && sweep.empty()
          ? std::vector<Case>{{"ref", 20, 1.0 / 3, 0.25}, {"cell", 20, 1.0, 0.25}, {"dt", 20, 1.0 / 3, 1.0}}
          : std::vector<Case>{{"ppc", 5, 1.0 / 3, 0.25},  {"ppc", 10, 1.0 / 3, 0.25},  {"ppc", 20, 1.0 / 3, 0.25},
                              {"ppc", 40, 1.0 / 3, 0.25}, {"cell", 20, 2.0 / 3, 0.25}, {"cell", 20, 1.0, 0.25},
                              {"cell", 20, 1.5, 0.25},    {"cell", 20, 2.0, 0.25},     {"dt", 20, 1.0 / 3, 0.5},
                              {"dt", 20, 1.0 / 3, 1.0},   {"dt", 20, 1.0 / 3, 1.5},    {"dt", 20, 1.0 / 3, 2.0}};
  std::vector<Case> cases;
  for (const Case& c : all)
    if (sweep.empty() || sweep == c.sweep) cases.push_back(c);
  const double batch_times = quick ? 50.0 : 1000.0;  // mean collision times per batch
  std::printf(
      "Couette flow, hard-sphere argon, Kn = %.2f, U = %.0f m/s, 20 batches of %.0f mean collision times; "
      "mu from the plates' shear over du/dy in the bulk, against Chapman-Enskog\n",
      kKnudsen, kWallSpeed, batch_times);
  print_header();
  std::vector<Run> runs;
  bool ok = true;
  for (const Case& c : cases) {
    runs.push_back(run(c.sweep, c.ppc, c.cell, c.dt, batch_times));
    const Run& r = runs.back();
    print_row(r);
    // The predictions are asymptotic in dx and dt: the smoke runs (dx, c dt up to lambda) are
    // held to them within 4 sigma + 5 %, the full sweeps only printed against them.
    const Estimate& v = r.result.viscosity_ratio;
    ok = ok && r.result.lost == 0 && (!quick || std::abs(v.mean - 1 - viscosity_error(r.spec)) < 4 * v.error + 0.05);
  }
  if (!csv.empty()) write_csv(csv, runs);
  if (!ok)
    std::printf("FAILED: a particle was lost, or a viscosity is off its prediction by more than 4 sigma + 5 %%\n");
  return ok ? 0 : 1;
}
