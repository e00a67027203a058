#pragma once
// Table 1 of REFERENCES.md (Strobl, Bannerman & Poeschel): the sphere cluster registered
// with bounding grids from one cell to the tracking mesh itself; primitives per cell,
// events generated and executed, and the speed-up, next to the published rows.

#include <string>
#include <vector>

namespace cosim::bench {

struct PruningOptions {
  int cells = 64;           // tracking mesh cells per axis (the paper's 64)
  long particles = 100000;  // the paper's 25.2e6; the figures are compared per particle-step
  int steps = 10;           // the paper's 1000
  std::vector<int> grids;   // bounding grids per axis (1 = none); empty: 1, 2, 4, ... cells
  std::string csv;          // also write the table here
};

// Prints the table; returns 1 if the executed events differ between grids or a particle
// is lost (the correctness check), else 0.
int run_pruning(const PruningOptions& options);

}  // namespace cosim::bench
