#include <petscsys.h>

#include <fstream>
#include <stdexcept>

#include "bench/fluid_accuracy/force_history.hpp"
#include "bench/fluid_accuracy/oscillating.hpp"

namespace cosim::bench {
namespace {

constexpr double kPeriod = 1 / kOscillationFrequency;
// The smoothing window: much longer than a step (about 10 steps at D/h = 5) and than the
// time between two face switches (h / U = 0.05 s at D/h = 5), much shorter than the period.
constexpr double kWindow = kPeriod / 20;

void write_histories(const std::string& path, const std::vector<OscillatingRun>& runs) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path);
  out << "level,method,time,drag,lift,drag_smooth,lift_smooth\n";
  for (const OscillatingRun& r : runs) {
    std::vector<double> time, drag, lift;
    for (const ForceSample& f : r.history) {
      time.push_back(f.time);
      drag.push_back(f.drag);
      lift.push_back(f.lift);
    }
    const std::vector<double> drag_smooth = smoothed(time, drag, kWindow), lift_smooth = smoothed(time, lift, kWindow);
    for (std::size_t i = 0; i < time.size(); ++i)
      out << r.level << ',' << r.method << ',' << time[i] << ',' << drag[i] << ',' << lift[i] << ',' << drag_smooth[i]
          << ',' << lift_smooth[i] << '\n';
  }
}

}  // namespace

void oscillating_study(bool quick, const std::string& csv, const std::vector<fluid::BodyOptions>& methods) {
  // Quick: a quarter period more than one, so that the last period starts after the
  // impulsive start (the body sets off at full speed through fluid at rest).
  const double periods = quick ? 1.25 : 2;
  PetscPrintf(PETSC_COMM_WORLD,
              "Oscillating cylinder, %.2f periods of %.1f s; over the last period: mean C_D, C_L, peak |C_D| "
              "(smooth), spurious part (C - local quadratic fit over %.2f s): RMS and max\n",
              periods, kPeriod, kWindow);
  PetscPrintf(PETSC_COMM_WORLD, "%-7s %-24s %6s %6s %9s %8s %8s %8s %9s %9s %9s %9s\n", "level", "method", "cells",
              "steps", "wall [s]", "mean C_D", "mean C_L", "peak C_D", "C_D rms", "C_D max", "C_L rms", "C_L max");
  std::vector<OscillatingRun> runs;
  for (const fluid::BodyOptions& method : methods)
    for (int d : quick ? std::vector{5, 10} : std::vector{5, 10, 20}) {
      runs.push_back(oscillating_cylinder(d, periods, method));
      const OscillatingRun& r = runs.back();
      const ForceSummary s = summarise(r.history, (periods - 1) * kPeriod, kWindow);
      PetscPrintf(PETSC_COMM_WORLD, "%-7s %-24s %6ld %6d %9.2f %8.4f %8.4f %8.3f %9.4f %9.4f %9.4f %9.4f\n",
                  r.level.c_str(), r.method.c_str(), r.cells, r.steps, r.seconds, s.mean_drag, s.mean_lift, s.peak_drag,
                  s.drag.rms, s.drag.max, s.lift.rms, s.lift.max);
    }
  PetscMPIInt rank = 0;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  if (!csv.empty() && rank == 0) write_histories(csv, runs);
}

}  // namespace cosim::bench
