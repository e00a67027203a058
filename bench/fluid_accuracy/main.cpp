// fluid_accuracy: what accuracy costs in time for the fluid's two body treatments (the
// immersed boundary and the staircase), on the Hasimoto sphere (F, at several positions
// in the cell per grid: the spread over the body's alignment to the grid) and the DFG 2D-1
// cylinder (C_D), each on several grid levels. Prints one row per run; --csv writes them too
// (plot.py draws error against wall time). --oscillating runs the oscillating-cylinder
// study instead (--csv: the force histories, plot_oscillating.py), --towed the time-step
// study of a moving sphere, --wall-approach that of a sphere closing on a wall, --duct the
// settling sphere's tank seen from the sphere, --pipe Poiseuille's flow in a round pipe
// made by a container. Serial
// or under mpirun (PETSC_COMM_WORLD).
#include <CLI/CLI.hpp>
#include <petscsys.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/fluid_accuracy/cases.hpp"
#include "bench/fluid_accuracy/oscillating.hpp"
#include "bench/fluid_accuracy/round_pipe.hpp"

using namespace cosim::bench;

namespace {

// The scene key pressure_update's values.
const std::map<std::string, cosim::fluid::navier_stokes::PressureUpdate> kPressureUpdates{
    {"standard", cosim::fluid::navier_stokes::PressureUpdate::standard},
    {"rotational", cosim::fluid::navier_stokes::PressureUpdate::rotational},
    {"exact", cosim::fluid::navier_stokes::PressureUpdate::exact}};

std::string describe(const cosim::fluid::navier_stokes::TimeStepOptions& stepping) {
  std::string update;
  for (const auto& [name, value] : kPressureUpdates)
    if (value == stepping.pressure_update) update = name;
  return "theta " + std::to_string(stepping.theta).substr(0, 4) + ", " + update + " pressure update" +
         (stepping.convection ? "" : ", Stokes flow");
}

void print_header() {
  PetscPrintf(PETSC_COMM_WORLD, "%-12s %-8s %-26s %7s %6s %9s %10s %10s %9s %9s\n", "case", "level", "method", "cells",
              "steps", "wall [s]", "value", "reference", "error", "check");
}

void print_row(const FluidRun& r) {
  PetscPrintf(PETSC_COMM_WORLD, "%-12s %-8s %-26s %7ld %6d %9.2f %10.4f %10.4f %+8.3f%% %9.5f\n", r.scene.c_str(),
              r.level.c_str(), r.method.c_str(), r.cells, r.steps, r.seconds, r.value, r.reference, 100 * r.error(),
              r.check);
}

void write_csv(const std::string& path, const std::vector<FluidRun>& runs) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path);
  out << "case,level,method,cells,steps,wall_seconds,value,reference,error,check\n";
  for (const FluidRun& r : runs)
    out << r.scene << ',' << r.level << ',' << r.method << ',' << r.cells << ',' << r.steps << ',' << r.seconds << ','
        << r.value << ',' << r.reference << ',' << r.error() << ',' << r.check << '\n';
}

// The k-th of a Halton sequence in [0, 1)^3 (bases 2, 3, 5): positions spread over a cell.
Eigen::Vector3d halton(int k) {
  Eigen::Vector3d x;
  const int bases[3] = {2, 3, 5};
  for (int d = 0; d < 3; ++d) {
    double f = 1, r = 0;
    for (int i = k + 1; i > 0; i /= bases[d]) {
      f /= bases[d];
      r += f * (i % bases[d]);
    }
    x[d] = r;
  }
  return x;
}

// Hasimoto sphere positions: the Halton indices first .. first + count - 1 (a first other
// than 0 splits one grid's positions over processes).
struct Positions {
  int first = 0, count = 8;
};

struct Settings {
  std::vector<cosim::fluid::BodyOptions> methods;
  std::vector<int> boxes, diameters;
  Positions positions;
  cosim::bench::StokesStepping stepping;  // Hasimoto's
  bool hasimoto = true, dfg = true;
};

// The k-th Hasimoto sphere centre on n^3 cells: within one cell around the box's centre,
// so that the spread over k is the method's dependence on how the sphere meets the grid.
Eigen::Vector3d sphere_centre(int n, int k) { return Eigen::Vector3d::Constant(0.5) + halton(k) / n; }

// h kappa of the Hasimoto sphere on n^3 cells: 2 h / a with a = 0.2 and h = 1 / n.
double sphere_h_kappa(int n) { return 10.0 / n; }

// Mean Hasimoto error of the immersed boundary over the given positions on n^3 cells.
double mean_hasimoto_error(int n, const cosim::fluid::ibm::IbmOptions& ibm, const Settings& s) {
  double mean = 0;
  const Positions& p = s.positions;
  for (int k = p.first; k < p.first + p.count; ++k)
    mean += hasimoto_sphere(n, ibm, sphere_centre(n, k), s.stepping).error() / p.count;
  return mean;
}

// The constant retraction (no curvature term) that zeroes the mean Hasimoto error on n^3
// cells, by the secant method (the error falls about linearly with the retraction), from
// the calibrated law's retraction there.
double zeroing_retraction(int n, cosim::fluid::ibm::IbmOptions ibm, const Settings& s) {
  const cosim::fluid::ibm::Retraction law = cosim::fluid::ibm::calibrated_retraction(ibm.kernel);
  double r0 = law.constant + law.curvature * sphere_h_kappa(n), r1 = r0 + 0.02;
  ibm.retraction = cosim::fluid::ibm::Retraction{r0, 0};
  double e0 = mean_hasimoto_error(n, ibm, s);
  for (int i = 0; i < 8; ++i) {
    ibm.retraction = cosim::fluid::ibm::Retraction{r1, 0};
    const double e1 = mean_hasimoto_error(n, ibm, s);
    PetscPrintf(PETSC_COMM_WORLD, "  %s, d/h %.1f: retraction %.4f -> mean error %+.3f %%\n",
                std::string(name(ibm.kernel)).c_str(), 0.4 * n, r1, 100 * e1);
    if (std::abs(e1) < 2e-4 || e1 == e0) break;
    const double r2 = r1 - e1 * (r1 - r0) / (e1 - e0);
    r0 = r1;
    e0 = e1;
    r1 = r2;
  }
  return r1;
}

// The retraction h (constant + curvature h kappa) that zeroes the Hasimoto error on both
// grids: on each the constant retraction R_n that does, then, as the sphere's
// h kappa, the line through (sphere_h_kappa(n), R_n).
// With one box, only its zeroing constant retraction (run the two boxes as two processes
// and put the line through them by hand to use both cores).
void calibrate(const std::vector<int>& boxes, const cosim::fluid::ibm::IbmOptions& ibm, const Settings& s) {
  if (boxes.size() == 1) {
    PetscPrintf(PETSC_COMM_WORLD, "zeroing retraction for %s at d/h %.1f: %.4f\n",
                std::string(name(ibm.kernel)).c_str(), 0.4 * boxes[0], zeroing_retraction(boxes[0], ibm, s));
    return;
  }
  if (boxes.size() != 2) throw std::invalid_argument("--calibrate needs one or two --boxes");
  const double r1 = zeroing_retraction(boxes[0], ibm, s), r2 = zeroing_retraction(boxes[1], ibm, s);
  const double k1 = sphere_h_kappa(boxes[0]), k2 = sphere_h_kappa(boxes[1]);
  const double curvature = (r1 - r2) / (k1 - k2), constant = r1 - curvature * k1;
  PetscPrintf(PETSC_COMM_WORLD,
              "calibrated retraction for %s: %.3f + %.3f h kappa cell widths (constant retractions %.4f at d/h %.1f, "
              "%.4f at d/h %.1f)\n",
              std::string(name(ibm.kernel)).c_str(), constant, curvature, r1, 0.4 * boxes[0], r2, 0.4 * boxes[1]);
}

// The towed sphere at each time step, finest last: the drag's error against the finest
// step's and its observed order in the step.
void towed_study(const std::vector<cosim::fluid::BodyOptions>& methods, int cells_per_diameter,
                 std::vector<double> cells_per_step, double reynolds, double rise,
                 const cosim::fluid::navier_stokes::TimeStepOptions& stepping) {
  std::sort(cells_per_step.rbegin(), cells_per_step.rend());
  PetscPrintf(PETSC_COMM_WORLD, "towed sphere, d/h %d, Re %g, speed reached over %g d/U, %s\n", cells_per_diameter,
              reynolds, rise, describe(stepping).c_str());
  PetscPrintf(PETSC_COMM_WORLD, "%-26s %10s %9s %6s %9s %10s %12s %7s %10s\n", "method", "cells/step", "nu dt/h2",
              "steps", "wall [s]", "drag", "vs finest", "order", "corr/step");
  for (const auto& method : methods) {
    std::vector<Towed> runs;
    for (double c : cells_per_step)
      runs.push_back(towed_sphere(method, cells_per_diameter, c, reynolds, rise, stepping));
    const double finest = runs.back().drag;
    for (std::size_t i = 0; i < runs.size(); ++i) {
      const Towed& r = runs[i];
      // From the differences between neighbouring steps (each halving the last, or not).
      double order = std::nan("");
      if (i + 2 < runs.size())
        order = std::log(std::abs((runs[i].drag - runs[i + 1].drag) / (runs[i + 1].drag - runs[i + 2].drag))) /
                std::log(runs[i].cells_per_step / runs[i + 1].cells_per_step);
      PetscPrintf(PETSC_COMM_WORLD, "%-26s %10.3f %9.3f %6d %9.1f %10.6f %+11.3f%% %7.2f %10.2f\n",
                  cosim::fluid::label(method).c_str(), r.cells_per_step, r.viscous_number, r.steps, r.seconds, r.drag,
                  100 * (r.drag - finest) / finest, order, r.corrections);
    }
  }
}

// The film correction cosim-rigidbody adds below the gap `range` the fluid resolves
// (rigidbody/solver/README.md "Lubrication"), 6 pi mu a^2 U (1/s - 1/range), over 6 pi mu a U,
// gaps in radii.
double film_correction(double gap, double range) { return gap < range ? 1 / gap - 1 / range : 0; }

// Largest relative error against Brenner's of `factors` (at `gaps`) with the film correction
// from `range` added.
double largest_film_error(const std::vector<double>& factors, const std::vector<double>& gaps, double range) {
  double largest = 0;
  for (std::size_t g = 0; g < gaps.size(); ++g) {
    const double brenner = brenner_wall_factor(gaps[g]);
    largest = std::max(largest, std::abs(factors[g] + film_correction(gaps[g], range) - brenner) / brenner);
  }
  return largest;
}

// The largest error against Brenner's over the gaps measured with the film correction from
// a range of one, a half, 0.4 and a third of a cell added to the grid's drag, and the range
// (in cells) that comes nearest.
void print_film_range(const std::vector<double>& factors, const std::vector<double>& gaps, int cells_per_diameter) {
  const double radius_in_cells = 0.5 * cells_per_diameter;
  PetscPrintf(PETSC_COMM_WORLD, "with the film correction from a range of");
  for (double cells : {1.0, 0.5, 0.4, 1.0 / 3.0})
    PetscPrintf(PETSC_COMM_WORLD, " %.2f cells: %.1f %%,", cells,
                100 * largest_film_error(factors, gaps, cells / radius_in_cells));
  double best = 0, best_error = std::numeric_limits<double>::infinity();
  for (double cells = 0.05; cells <= 1.5; cells += 0.01)
    if (const double e = largest_film_error(factors, gaps, cells / radius_in_cells); e < best_error) {
      best = cells;
      best_error = e;
    }
  PetscPrintf(PETSC_COMM_WORLD, " nearest from %.2f cells: %.1f %% (the largest error against Brenner's)\n", best,
              100 * best_error);
}

// The sphere driven towards the floor at each time step, finest last: its drag at each gap
// over Stokes's, as the finest step's times one plus the error against it (error_against).
void wall_approach_study(const std::vector<cosim::fluid::BodyOptions>& methods, int cells_per_diameter,
                         std::vector<double> viscous_numbers, double reynolds, std::vector<double> gaps,
                         const cosim::fluid::navier_stokes::TimeStepOptions& stepping, const WallApproachBox& box) {
  std::sort(viscous_numbers.rbegin(), viscous_numbers.rend());
  std::sort(gaps.rbegin(), gaps.rend());
  if (gaps.front() >= box.start_gap || gaps.back() <= 0)
    throw std::invalid_argument("--gaps: between 0 and --start-gap radii");
  PetscPrintf(PETSC_COMM_WORLD,
              "sphere driven towards a wall from a gap of %.2f radii, d/h %d, Re %g, %s: F / (6 pi mu a U) at gaps of",
              box.start_gap, cells_per_diameter, reynolds, describe(stepping).c_str());
  for (double g : gaps) PetscPrintf(PETSC_COMM_WORLD, " %.2f", g);
  PetscPrintf(PETSC_COMM_WORLD, " radii (Brenner's:");
  for (double g : gaps) PetscPrintf(PETSC_COMM_WORLD, " %.4f", brenner_wall_factor(g));
  PetscPrintf(PETSC_COMM_WORLD, ")\n%-26s %9s %10s %6s %9s %10s  %s\n", "method", "nu dt/h2", "cells/step", "steps",
              "wall [s]", "corr/step", "F / (6 pi mu a U) (vs finest)");
  for (const auto& method : methods) {
    std::vector<WallApproach> runs;
    for (double v : viscous_numbers)
      runs.push_back(sphere_approaching_a_wall(method, cells_per_diameter, v, reynolds, gaps, stepping, box));
    const WallApproach& finest = runs.back();
    for (std::size_t i = 0; i < runs.size(); ++i) {
      const WallApproach& r = runs[i];
      PetscPrintf(PETSC_COMM_WORLD, "%-26s %9.3f %10.4f %6d %9.1f %10.2f ", cosim::fluid::label(method).c_str(),
                  viscous_numbers[i], r.cells_per_step, r.steps, r.seconds, r.corrections);
      for (std::size_t g = 0; g < gaps.size(); ++g) {
        const double error = &r == &finest ? 0.0 : error_against(r, finest, gaps[g]);
        PetscPrintf(PETSC_COMM_WORLD, " %8.4f (%+6.2f%%)", finest.factors[g] * (1 + error), 100 * error);
      }
      PetscPrintf(PETSC_COMM_WORLD, "\n");
    }
    print_film_range(finest.factors, gaps, cells_per_diameter);
    PetscPrintf(PETSC_COMM_WORLD, "wall ms per step, by stage:");
    for (const char* stage : cosim::fluid::navier_stokes::kStageNames) PetscPrintf(PETSC_COMM_WORLD, " %s,", stage);
    PetscPrintf(PETSC_COMM_WORLD, " at each nu dt / h^2\n");
    for (std::size_t i = 0; i < runs.size(); ++i) {
      PetscPrintf(PETSC_COMM_WORLD, "  %6.3f:", viscous_numbers[i]);
      for (double seconds : runs[i].stages.all())
        PetscPrintf(PETSC_COMM_WORLD, " %8.2f", 1e3 * seconds / runs[i].steps);
      PetscPrintf(PETSC_COMM_WORLD, "\n");
    }
  }
}

// The sphere held in the sliding duct at each grid.
void duct_study(const std::vector<cosim::fluid::BodyOptions>& methods, const std::vector<int>& diameters,
                double reynolds) {
  PetscPrintf(PETSC_COMM_WORLD, "sphere held in the sliding duct, Re %g\n", reynolds);
  PetscPrintf(PETSC_COMM_WORLD, "%-26s %5s %8s %6s %9s %14s\n", "method", "d/h", "cells", "steps", "wall [s]",
              "F/(3 pi mu U d)");
  for (const auto& method : methods)
    for (int n : diameters) {
      const DuctDrag r = sphere_in_sliding_duct(method, n, reynolds);
      PetscPrintf(PETSC_COMM_WORLD, "%-26s %5d %8ld %6d %9.1f %14.5f\n", cosim::fluid::label(method).c_str(), n,
                  r.cells, r.steps, r.seconds, r.factor);
    }
}

// Poiseuille's flow in a round pipe made by a container, per kernel and grid.
void pipe_study(const std::vector<int>& diameters) {
  PetscPrintf(PETSC_COMM_WORLD, "round pipe (a container), axis (0.37, 0.61) h off the grid's lines\n");
  PetscPrintf(PETSC_COMM_WORLD, "| kernel | D/h | flow rate | profile (of u_max) | cells | steps | wall [s] |\n");
  PetscPrintf(PETSC_COMM_WORLD, "|---|---|---|---|---|---|---|\n");
  using cosim::fluid::ibm::DeltaKernel;
  for (DeltaKernel kernel : {DeltaKernel::roma3, DeltaKernel::peskin4, DeltaKernel::bao6})
    for (int n : diameters) {
      // Room outside the pipe for the solid held beyond the widest kernel.
      const PipeFlow r = round_pipe(n, {0.37, 0.61}, 14, kernel);
      PetscPrintf(PETSC_COMM_WORLD, "| %s | %d | %+.2f %% | %.2f %% | %ld | %d | %.1f |\n",
                  std::string(name(kernel)).c_str(), n, 100 * r.flow_rate_error, 100 * r.profile_error, r.cells,
                  r.steps, r.seconds);
    }
}

// The Galilean check at each time step: the towed sphere's drag against the fixed one's.
void moving_frame_study(const std::vector<cosim::fluid::BodyOptions>& methods, int n,
                        const std::vector<double>& cells_per_step, double reynolds) {
  PetscPrintf(PETSC_COMM_WORLD, "Hasimoto sphere fixed, then towed through fluid at rest, d/h %.1f\n", 0.4 * n);
  PetscPrintf(PETSC_COMM_WORLD, "%-26s %6s %10s %9s %9s %11s %11s %9s\n", "method", "Re", "cells/step", "nu dt/h2",
              "wall [s]", "fixed", "towed", "towed/fixed");
  for (const auto& method : methods)
    for (double c : cells_per_step) {
      const MovingFrame r = moving_frame(n, method, reynolds, c);
      PetscPrintf(PETSC_COMM_WORLD, "%-26s %6.3f %10.4f %9.4f %9.1f %11.4f %11.4f %+10.3f%%\n",
                  cosim::fluid::label(method).c_str(), r.reynolds, r.cells_per_step, r.viscous_number, r.seconds,
                  r.fixed_drag, r.moving_drag, 100 * r.error());
    }
}

void study(const Settings& s, const std::string& csv) {
  std::vector<FluidRun> runs;
  print_header();
  for (const auto& method : s.methods) {
    double last_mean = 0;
    int last_n = 0;
    for (int n : s.hasimoto ? s.boxes : std::vector<int>{}) {
      std::vector<double> errors;
      for (int k = s.positions.first; k < s.positions.first + s.positions.count; ++k) {
        runs.push_back(hasimoto_sphere(n, method, sphere_centre(n, k), s.stepping));
        print_row(runs.back());
        errors.push_back(runs.back().error());
      }
      double mean = 0;
      for (double e : errors) mean += e / static_cast<double>(errors.size());
      const auto [lo, hi] = std::minmax_element(errors.begin(), errors.end());
      PetscPrintf(PETSC_COMM_WORLD,
                  "  Hasimoto d/h %.1f, %s: mean error %+.3f %%, spread over %d positions %.3f %% (%+.3f .. %+.3f)\n",
                  0.4 * n, cosim::fluid::label(method).c_str(), 100 * mean, s.positions.count, 100 * (*hi - *lo),
                  100 * *lo, 100 * *hi);
      // The observed order of the mean error; meaningless where a calibration makes it cross zero.
      if (last_n > 0)
        PetscPrintf(PETSC_COMM_WORLD, "  observed order of the mean error from d/h %.1f to %.1f: %.2f\n", 0.4 * last_n,
                    0.4 * n, std::log(std::abs(last_mean / mean)) / std::log(double(n) / last_n));
      last_mean = mean;
      last_n = n;
    }
    for (int d : s.dfg ? s.diameters : std::vector<int>{}) {
      runs.push_back(dfg_cylinder(d, method));
      print_row(runs.back());
    }
  }
  PetscMPIInt rank = 0;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  if (!csv.empty() && rank == 0) write_csv(csv, runs);
}

}  // namespace

int main(int argc, char** argv) {
  std::string csv, method = "both", kernel = "roma3";
  bool quick = false, oscillating = false, only_hasimoto = false, only_dfg = false, calibrating = false;
  cosim::fluid::ibm::IbmOptions ibm;
  Settings s;
  s.boxes = {20, 30, 40, 60};
  s.diameters = {10, 20, 40};
  CLI::App app{"fluid_accuracy: accuracy against wall time of the body treatments (Hasimoto sphere, DFG cylinder)"};
  app.add_option("--csv", csv, "Also write the table (with --oscillating: the force histories) to this CSV file");
  app.add_flag("--quick", quick,
               "Hasimoto at d/h 4.8 on one position for 500 steps, DFG at D/h 5 (the oscillating cylinder: D/h 5, 10 "
               "over 1.25 periods)");
  app.add_flag("--oscillating", oscillating, "The oscillating cylinder (D/h 5, 10, 20, two periods) instead");
  std::vector<double> towed;
  app.add_option(
      "--towed", towed,
      "The towed sphere (--diameter cells across) instead, at these time steps in cells the body moves per step");
  double rise = 0;
  app.add_option("--rise", rise, "The towed sphere's speed rises from rest over this time, in d / U (0: at once)")
      ->check(CLI::NonNegativeNumber);
  double reynolds = 1.5;
  app.add_option(
      "--reynolds", reynolds,
      "The towed sphere's and the wall approach's Reynolds number (ten Cate E1 1.5, E4 32); with --moving-frame Hasimoto's, "
      "estimated from Stokes drag");
  app.add_option("--method", method, "ibm, staircase or both")->check(CLI::IsMember({"ibm", "staircase", "both"}));
  app.add_option("--kernel", kernel, "IBM kernel")->check(CLI::IsMember({"roma3", "peskin4", "bao6"}));
  double retraction = -1, curvature = 0;
  app.add_option("--retraction", retraction, "IBM marker retraction in cell widths (constant part)");
  app.add_option("--curvature-retraction", curvature, "IBM marker retraction's curvature part (with --retraction)");
  app.add_option("--sweeps", ibm.sweeps, "IBM forcing solve's iterations per step, at most");
  app.add_option("--corrections", ibm.corrections, "IBM no-slip corrections per step after the projection, at most")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--no-slip-tolerance", ibm.no_slip_tolerance,
                 "IBM root mean square slip after the corrections, of the largest velocity at the markers");
  app.add_option("--spacing", ibm.spacing, "IBM marker spacing in cell widths");
  app.add_flag("--spread-at-theta", ibm.spread_at_theta,
               "IBM: a moving marker spreads its impulse from where it was at t_n + theta dt");
  app.add_option("--boxes", s.boxes, "Hasimoto grids (cells per side; d/h = 0.4 n)");
  app.add_option("--diameters", s.diameters, "DFG cells per diameter");
  app.add_option("--positions", s.positions.count, "Hasimoto sphere positions per grid")->check(CLI::PositiveNumber);
  app.add_option("--first-position", s.positions.first,
                 "Index of the first Hasimoto position (split one grid's positions over processes)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--viscous-number", s.stepping.viscous_number, "Hasimoto's step as nu dt / h^2")
      ->check(CLI::PositiveNumber);
  std::optional<double> theta;
  cosim::fluid::navier_stokes::TimeStepOptions moving_steps;  // the towed sphere's and the wall approach's
  app.add_option("--pressure-update", moving_steps.pressure_update,
                 "The towed sphere's and the wall approach's pressure update (the scene key pressure_update)")
      ->transform(CLI::CheckedTransformer(kPressureUpdates));
  app.add_option("--theta", theta,
                 "The implicit weight of the viscous term (Hasimoto's default 1; the towed sphere's and the wall "
                 "approach's the fluid's default, 0.5)")
      ->check(CLI::Range(0.5, 1.0));
  app.add_flag(
      "--stokes", [&](std::int64_t) { moving_steps.convection = false; },
      "The towed sphere and the wall approach in unsteady Stokes flow: no advection (the scene key "
      "convection: false)");
  app.add_flag("--hasimoto", only_hasimoto, "Only the Hasimoto sphere");
  app.add_flag("--dfg", only_dfg, "Only the DFG cylinder");
  app.add_flag("--calibrate", calibrating,
               "Find the IBM retraction (constant and curvature part) that zeroes the mean Hasimoto error on both of "
               "two --boxes over --positions positions");
  std::vector<double> moving;
  app.add_option("--moving-frame", moving,
                 "Galilean check instead: Hasimoto's sphere (the first --boxes) at --reynolds, fixed, then towed "
                 "through fluid at rest, at these time steps in cells the body moves per step");
  std::vector<double> wall;
  app.add_option("--wall-approach", wall,
                 "A sphere driven towards a no-slip wall instead (at --reynolds, --diameter cells across), at these "
                 "time steps as nu dt / h^2");
  std::vector<double> gaps{2, 1, 0.5, 0.25};
  app.add_option("--gaps", gaps, "The wall approach's gaps to the wall in radii (below --start-gap)");
  WallApproachBox box;
  app.add_option("--start-gap", box.start_gap, "The wall approach's gap at the start, from rest, in radii")
      ->check(CLI::Range(0.5, 5.0));
  int diameter = 6;
  app.add_option("--diameter", diameter, "The towed sphere's and the wall approach's cells per diameter")
      ->check(CLI::Range(2, 32));
  std::vector<int> duct;
  app.add_option("--duct", duct,
                 "ten Cate's tank seen from the sphere instead (held in a square duct whose walls slide past, at "
                 "--reynolds), at these cells per diameter (multiples of 3)");
  std::vector<int> pipe;
  app.add_option("--pipe", pipe,
                 "Poiseuille's flow in a round pipe made by a container instead, at these cells per diameter, every "
                 "kernel");
  CLI11_PARSE(app, argc, argv);
  if (theta) s.stepping.theta = moving_steps.theta = *theta;
  if (retraction >= 0) ibm.retraction = cosim::fluid::ibm::Retraction{retraction, curvature};
  ibm.kernel = kernel == "roma3"     ? cosim::fluid::ibm::DeltaKernel::roma3
               : kernel == "peskin4" ? cosim::fluid::ibm::DeltaKernel::peskin4
                                     : cosim::fluid::ibm::DeltaKernel::bao6;
  if (method != "staircase") s.methods.push_back(ibm);
  if (method != "ibm")
    s.methods.push_back(
        cosim::fluid::staircase::FbmOptions{.offset = cosim::fluid::staircase::kCalibratedSurfaceOffset});
  s.hasimoto = !only_dfg;
  s.dfg = !only_hasimoto;
  if (quick) {  // the pipeline end to end, not the steady state
    s.boxes = {12};
    s.diameters = {5};
    s.positions = {0, 1};
    s.stepping.max_steps = 500;
  }

  // PETSc sees no arguments: the options are the study's.
  int petsc_argc = 1;
  char** petsc_argv = argv;
  PetscCall(PetscInitialize(&petsc_argc, &petsc_argv, nullptr, nullptr));
  int result = 1;
  try {
    if (!moving.empty())
      moving_frame_study(s.methods, s.boxes.front(), moving, reynolds);
    else if (calibrating)
      calibrate(s.boxes, ibm, s);
    else if (!pipe.empty())
      pipe_study(pipe);
    else if (!duct.empty())
      duct_study(s.methods, duct, reynolds);
    else if (!wall.empty())
      wall_approach_study(s.methods, diameter, wall, reynolds, gaps, moving_steps, box);
    else if (!towed.empty())
      towed_study(s.methods, diameter, towed, reynolds, rise, moving_steps);
    else if (oscillating)
      oscillating_study(quick, csv, s.methods);
    else
      study(s, csv);
    result = 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fluid_accuracy: %s\n", e.what());
  }
  PetscCall(PetscFinalize());
  return result;
}
