// fluid_throughput: how fast cosim_fluid steps a three-dimensional lid-driven cavity (Re
// 100) on N^3 cells, and how much memory it needs per cell, serially or under mpirun;
// --openfoam runs the same case with icoFoam and compares speed and the centre-line
// velocity after the same steps. Prints one row per run; --csv writes them too.
#include <petscsys.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "bench/fluid_throughput/cavity.hpp"
#include "bench/fluid_throughput/openfoam_case.hpp"
#include "bench/fluid_throughput/table.hpp"

using namespace cosim::bench;

namespace {

constexpr double kGoalBytesPerCell = 0.6 * 1024;  // net of the process baseline
constexpr double kGoalSpeedup = 2;                // cell-updates per CPU second against OpenFOAM's

int rank() {
  int r = 0;
  MPI_Comm_rank(PETSC_COMM_WORLD, &r);
  return r;
}

// Runs f on rank 0 only, for OpenFOAM, which runs as a child of rank 0: the other ranks
// wait without spinning in MPI (which would take a core from it). What f throws is thrown
// on every rank.
void on_rank0(const std::function<void()>& f) {
  std::string error;
  if (rank() == 0) {
    try {
      f();
    } catch (const std::exception& e) {
      error = e.what();
    }
  }
  MPI_Request done;
  MPI_Ibarrier(PETSC_COMM_WORLD, &done);
  for (int finished = 0; !finished; usleep(100000)) MPI_Test(&done, &finished, MPI_STATUS_IGNORE);
  int failed = !error.empty();
  MPI_Bcast(&failed, 1, MPI_INT, 0, PETSC_COMM_WORLD);
  if (failed) throw std::runtime_error(rank() == 0 ? error : "OpenFOAM failed on rank 0");
}

// Every rank gets the results, so that all hold the same table.
ThroughputRun openfoam_run(const Cavity& cavity, int ranks) {
  ThroughputRun run;
  on_rank0([&] { run = run_openfoam(cavity, ranks); });
  double timing[] = {run.first_step_seconds, run.cpu_seconds_per_step, static_cast<double>(run.timed_steps)};
  MPI_Bcast(timing, 3, MPI_DOUBLE, 0, PETSC_COMM_WORLD);
  run.centre_line.resize(static_cast<std::size_t>(cavity.n));
  MPI_Bcast(run.centre_line.data(), cavity.n, MPI_DOUBLE, 0, PETSC_COMM_WORLD);
  run.solver = "OpenFOAM";
  run.ranks = ranks;
  run.cavity = cavity;
  run.first_step_seconds = timing[0];
  run.cpu_seconds_per_step = timing[1];
  run.timed_steps = static_cast<int>(timing[2]);
  return run;
}

// Where the two centre lines differ most, with Stokes' first problem there as a yardstick.
void print_centre_lines(const ThroughputRun& ours, const ThroughputRun& openfoam) {
  const Cavity& c = ours.cavity;
  int worst = 0;
  for (int k = 0; k < c.n; ++k)
    if (std::abs(ours.centre_line[k] - openfoam.centre_line[k]) >
        std::abs(ours.centre_line[worst] - openfoam.centre_line[worst]))
      worst = k;
  const double u = ours.centre_line[worst], v = openfoam.centre_line[worst];
  PetscPrintf(PETSC_COMM_WORLD,
              "  centre line u(0.5, 0.5, z) at t = %.4f: max |ours - OpenFOAM| = %.4f U_lid, at z = %.4f "
              "(ours %.4f, OpenFOAM %.4f, Stokes layer %.4f)\n",
              c.end_time(), std::abs(u - v) / Cavity::kLidVelocity, c.centre(worst), u, v,
              c.stokes_layer(c.centre(worst)));
}

void print_memory_goal(const ThroughputRun& r) {
  const double net = (r.memory.peak_bytes - r.memory.baseline_bytes) / static_cast<double>(r.cavity.cells());
  PetscPrintf(PETSC_COMM_WORLD,
              "  memory: %.0f bytes per cell net of the baseline (%.0f MB on %d rank(s)); goal <= %.0f: %s\n", net,
              r.memory.baseline_bytes / 1e6, r.ranks, kGoalBytesPerCell, net <= kGoalBytesPerCell ? "met" : "NOT met");
}

// Per CPU second: OpenFOAM reports CPU time only, at whole-second wall resolution.
void print_comparison(const ThroughputRun& ours, const ThroughputRun& openfoam) {
  const double speedup = ours.cell_updates_per_cpu_second() / openfoam.cell_updates_per_cpu_second();
  PetscPrintf(PETSC_COMM_WORLD, "  against OpenFOAM: %.2fx its cell-updates per CPU second; goal >= %.0fx: %s\n",
              speedup, kGoalSpeedup, speedup >= kGoalSpeedup ? "met" : "NOT met");
  print_centre_lines(ours, openfoam);
}

// What makes a run's figures worth printing (and the --quick ctest fail otherwise): a
// divergence-free flow and, under the lid, the impulsively started plate's layer to 0.15 of
// the lid velocity (the side walls' return flow and a layer one or two cells thick take the
// rest: 0.09 at 16^3 after 4 steps, 0.04 at 32^3 after 3).
bool physical(const ThroughputRun& r) {
  const Cavity& c = r.cavity;
  const int top = c.n - 1;
  const double u = r.centre_line.at(static_cast<std::size_t>(top)), stokes = c.stokes_layer(c.centre(top));
  const bool ok = r.max_divergence < 1e-8 && std::abs(u - stokes) < 0.15 * Cavity::kLidVelocity;
  PetscPrintf(PETSC_COMM_WORLD, "  top cell u %.4f against the Stokes layer's %.4f, max divergence %.1e: %s\n", u,
              stokes, r.max_divergence, ok ? "physical" : "NOT physical");
  return ok;
}

// What a moving body adds to a step (the goal: at most 1.1 times the step without).
void print_body_cost(const ThroughputRun& with, const ThroughputRun& without) {
  const double ratio = with.cpu_seconds_per_step / without.cpu_seconds_per_step;
  PetscPrintf(PETSC_COMM_WORLD,
              "  %s: a step with the moving sphere costs %.3fx the step without (goal <= 1.1: %s); forcing and loads "
              "%.4f s, pressure solve %.4f s against %.4f s\n",
              with.solver.c_str(), ratio, ratio <= 1.1 ? "met" : "NOT met", with.forcing_seconds_per_step,
              with.pressure_seconds_per_step, without.pressure_seconds_per_step);
}

int study(const std::vector<int>& sizes, int steps, double viscous_number, bool openfoam, bool bodies,
          const std::string& csv) {
  for (int n : sizes)
    if (n < 4 || n % 2) throw std::invalid_argument("-n: the cells per side must be even and at least 4");
  if (steps < (openfoam ? 3 : 2)) throw std::invalid_argument("--steps: at least 2 (3 with --openfoam)");
  int ranks = 1;
  MPI_Comm_size(PETSC_COMM_WORLD, &ranks);
  if (openfoam) on_rank0([&] { require_openfoam(ranks); });  // before minutes of our own runs
  std::vector<ThroughputRun> runs;
  PetscPrintf(PETSC_COMM_WORLD,
              "Lid-driven cavity, Re %.0f, lid at z = 1, Courant %.1f; first step excluded from the timing\n",
              Cavity::kReynolds, Cavity::kCourant);
  if (viscous_number > 0) PetscPrintf(PETSC_COMM_WORLD, "nu dt / h^2 = %g in place of Re's\n", viscous_number);
  print_header();
  bool all_physical = true;
  for (int n : sizes) {
    const Cavity cavity{.n = n, .steps = steps, .viscous_number = viscous_number};
    const std::size_t ours = runs.size();
    runs.push_back(run_cavity(cavity));
    print_row(runs[ours]);
    print_memory_goal(runs[ours]);
    all_physical = physical(runs[ours]) && all_physical;
    if (bodies)
      for (CavityBody body : {CavityBody::ibm, CavityBody::staircase}) {
        Cavity with = cavity;
        with.body = body;
        runs.push_back(run_cavity(with));
        print_row(runs.back());
        print_body_cost(runs.back(), runs[ours]);
      }
    if (!openfoam) continue;
    runs.push_back(openfoam_run(cavity, ranks));
    print_row(runs.back());
    print_comparison(runs[ours], runs.back());
  }
  if (!csv.empty() && rank() == 0) write_csv(csv, runs);
  return all_physical ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<int> sizes{64, 128};
  int steps = 5;
  bool quick = false, openfoam = false, bodies = false;
  double viscous_number = 0;
  std::string csv;
  CLI::App app{"fluid_throughput: cell-updates per second and memory per cell of cosim_fluid (3D lid-driven cavity)"};
  app.add_option("-n", sizes, "Cells per side, one run each (even)")->capture_default_str();
  app.add_option("--steps", steps, "Time steps per run, the first being the untimed warm-up")->capture_default_str();
  app.add_flag("--quick", quick, "Smoke run: 16^3, 4 steps");
  app.add_option("--viscous-number", viscous_number,
                 "nu dt / h^2 in place of Re 100's (the viscous solve's stiffness); the lid layer's check then "
                 "compares with Stokes' layer of that nu");
  app.add_flag("--openfoam", openfoam, "Also run icoFoam on the same case and compare");
  app.add_option("--csv", csv, "Also write the table to this CSV file");
  app.add_flag("--bodies", bodies,
               "Also run each size with a sphere (d = N/4 cells) moving through the cavity, held by the immersed "
               "boundary and by the staircase, and compare their steps with the plain one's");
  CLI11_PARSE(app, argc, argv);
  if (quick) sizes = {16}, steps = 4;

  // PETSc sees no arguments: the options are the study's.
  int petsc_argc = 1;
  char** petsc_argv = argv;
  PetscCall(PetscInitialize(&petsc_argc, &petsc_argv, nullptr, nullptr));
  int result = 1;
  try {
    // The pressure-solve time comes from PETSc's event log.
    PetscCall(PetscLogDefaultBegin());
    result = study(sizes, steps, viscous_number, openfoam, bodies, csv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fluid_throughput: %s\n", e.what());
  }
  PetscCall(PetscFinalize());
  return result;
}
