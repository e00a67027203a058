// fluid_accuracy: what accuracy costs in time for the fictitious boundary method, on the
// DFG 2D-1 cylinder (C_D) and the Hasimoto sphere (F), each on several grid levels with
// point-sampled and sub-sampled alpha. Prints one row per run; --csv writes them too
// (plot.py draws error against wall time). --oscillating runs the oscillating-cylinder
// study instead (--csv: the force histories, plot_oscillating.py). Serial or under mpirun
// (PETSC_COMM_WORLD).
#include <CLI/CLI.hpp>
#include <petscsys.h>

#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <vector>

#include "cases.hpp"
#include "oscillating.hpp"

using namespace cosim::bench;

namespace {

constexpr int kSubsamples = 4;  // the sub-sampled alpha: 4^3 points per control volume

void print_header() {
  PetscPrintf(PETSC_COMM_WORLD, "%-14s %-8s %-8s %7s %6s %9s %10s %10s %9s\n", "case", "level", "alpha", "cells",
              "steps", "wall [s]", "value", "reference", "error");
}

void print_row(const FluidRun& r) {
  PetscPrintf(PETSC_COMM_WORLD, "%-14s %-8s %-8s %7ld %6d %9.2f %10.4f %10.4f %+8.2f%%\n", r.scene.c_str(),
              r.level.c_str(), r.alpha.c_str(), r.cells, r.steps, r.seconds, r.value, r.reference, 100 * r.error());
}

void write_csv(const std::string& path, const std::vector<FluidRun>& runs) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path);
  out << "case,level,alpha,cells,steps,wall_seconds,value,reference,error\n";
  for (const FluidRun& r : runs)
    out << r.scene << ',' << r.level << ',' << r.alpha << ',' << r.cells << ',' << r.steps << ',' << r.seconds << ','
        << r.value << ',' << r.reference << ',' << r.error() << '\n';
}

void study(bool quick, bool finest, const std::string& csv) {
  std::vector<FluidRun> runs;
  auto record = [&](FluidRun r) {
    print_row(r);
    runs.push_back(std::move(r));
  };
  print_header();
  const std::vector<int> diameters = quick ? std::vector{5, 10} : std::vector{5, 10, 20};
  const std::vector<int> boxes = quick ? std::vector{8, 12} : std::vector{8, 12, 16, 24};
  auto dfg = [&](int d, int s) {
    double lift = 0;
    record(dfg_cylinder(d, s, &lift));
    PetscPrintf(PETSC_COMM_WORLD, "%33s(C_L %.4f, reference 0.010619)\n", "", lift);
  };
  for (int d : diameters)
    for (int s : {1, kSubsamples}) dfg(d, s);
  // Point-sampled only: it alone takes four times as long as the rest, and at D/h = 20 the
  // sub-samples moved C_D by 1e-4 of itself.
  if (finest) dfg(40, 1);
  for (int n : boxes)
    for (int s : {1, kSubsamples}) record(hasimoto_sphere(n, s));
  PetscMPIInt rank = 0;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  if (!csv.empty() && rank == 0) write_csv(csv, runs);
}

}  // namespace

int main(int argc, char** argv) {
  std::string csv;
  bool quick = false, finest = false, oscillating = false;
  CLI::App app{"fluid_accuracy: accuracy against wall time of the FBM (DFG cylinder, Hasimoto sphere)"};
  app.add_option("--csv", csv, "Also write the table (with --oscillating: the force histories) to this CSV file");
  app.add_flag("--quick", quick, "Only the two coarsest levels of each case (D/h 5, 10; 8^3, 12^3; 1.25 periods)");
  app.add_flag("--finest", finest, "Also DFG at D/h 40, point-sampled alpha only (17 min more on a busy machine)");
  app.add_flag("--oscillating", oscillating, "The oscillating cylinder (D/h 5, 10, 20, two periods) instead");
  CLI11_PARSE(app, argc, argv);

  // PETSc sees no arguments: the options are the study's.
  int petsc_argc = 1;
  char** petsc_argv = argv;
  PetscCall(PetscInitialize(&petsc_argc, &petsc_argv, nullptr, nullptr));
  int result = 1;
  try {
    if (oscillating)
      oscillating_study(quick, csv);
    else
      study(quick, finest, csv);
    result = 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fluid_accuracy: %s\n", e.what());
  }
  PetscCall(PetscFinalize());
  return result;
}
