#include "bench/fluid_throughput/table.hpp"

#include <petscsys.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace cosim::bench {
namespace {

constexpr double kKiB = 1024;

double kib_per_cell(double bytes, const Cavity& c) { return bytes / kKiB / static_cast<double>(c.cells()); }

// "-" for what a solver's run does not measure.
std::string cell(const char* format, double value) {
  if (std::isnan(value)) return "-";
  char text[32];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

}  // namespace

void print_header() {
  const char* format = "%-11s %5s %4s %8s %5s %9s %9s %9s %10s %10s %9s %6s %8s %8s %8s\n";
  PetscPrintf(PETSC_COMM_WORLD, format, "solver", "ranks", "N", "cells", "steps", "first", "step", "step", "cell-upd/s",
              "cell-upd/s", "p solve", "p its", "peak KB", "net KB", "max div");
  PetscPrintf(PETSC_COMM_WORLD, format, "", "", "", "", "", "cpu [s]", "wall [s]", "cpu [s]", "wall", "cpu", "wall [s]",
              "", "per cell", "per cell", "");
}

void print_row(const ThroughputRun& r) {
  const MemoryUse& m = r.memory;
  PetscPrintf(PETSC_COMM_WORLD, "%-11s %5d %4d %8ld %5d %9.3f %9s %9.4f %10s %10.3e %9s %6s %8s %8s %8s\n",
              r.solver.c_str(), r.ranks, r.cavity.n, r.cavity.cells(), r.cavity.steps, r.first_step_seconds,
              cell("%.4f", r.seconds_per_step).c_str(), r.cpu_seconds_per_step,
              cell("%.3e", r.cell_updates_per_second()).c_str(), r.cell_updates_per_cpu_second(),
              cell("%.4f", r.pressure_seconds_per_step).c_str(), cell("%.1f", r.pressure_iterations_per_step).c_str(),
              cell("%.3f", kib_per_cell(m.peak_bytes, r.cavity)).c_str(),
              cell("%.3f", kib_per_cell(m.peak_bytes - m.baseline_bytes, r.cavity)).c_str(),
              cell("%.1e", r.max_divergence).c_str());
}

void write_csv(const std::string& path, const std::vector<ThroughputRun>& runs) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path);
  out << "solver,ranks,n,cells,steps,timed_steps,first_step_cpu_s,step_wall_s,step_cpu_s,cell_updates_per_s,"
         "cell_updates_per_cpu_s,pressure_wall_s_per_step,pressure_iterations_per_step,peak_kib_per_cell,"
         "net_kib_per_cell,max_divergence\n";
  for (const ThroughputRun& r : runs) {
    const MemoryUse& m = r.memory;
    out << r.solver << ',' << r.ranks << ',' << r.cavity.n << ',' << r.cavity.cells() << ',' << r.cavity.steps << ','
        << r.timed_steps << ',' << r.first_step_seconds << ',' << r.seconds_per_step << ',' << r.cpu_seconds_per_step
        << ',' << r.cell_updates_per_second() << ',' << r.cell_updates_per_cpu_second() << ','
        << r.pressure_seconds_per_step << ',' << r.pressure_iterations_per_step << ','
        << kib_per_cell(m.peak_bytes, r.cavity) << ',' << kib_per_cell(m.peak_bytes - m.baseline_bytes, r.cavity) << ','
        << r.max_divergence << '\n';
  }
}

}  // namespace cosim::bench
