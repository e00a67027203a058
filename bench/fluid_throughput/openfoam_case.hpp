// The same cavity with OpenFOAM's icoFoam (PISO), for comparison: the case is written to a
// temporary directory, meshed with blockMesh, run serially or decomposed over `ranks`
// with mpirun, and read back. Needs an OpenFOAM installation (Debian: package openfoam).
// Not collective: call these on one rank.
#pragma once

#include "bench/fluid_throughput/cavity.hpp"

namespace cosim::bench {

// Throws, naming what is missing, unless blockMesh and icoFoam (and for several ranks
// decomposePar, reconstructPar and mpirun) are found.
void require_openfoam(int ranks);

// cpu_seconds_per_step is from icoFoam's ExecutionTime (CPU time of its rank 0) over steps
// 2 to K-1: the first includes the setup, the last writes the fields. OpenFOAM prints wall
// time in whole seconds only, so seconds_per_step stays unmeasured. Needs cavity.steps >= 3.
// Fills the timing and the centre line; the caller labels the run.
ThroughputRun run_openfoam(const Cavity& cavity, int ranks);

}  // namespace cosim::bench
