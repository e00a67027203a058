// Resident memory of the whole run: the ranks' peak RSS summed, and the baseline the
// process had before the measured work, so per-cell figures can be given net of MPI,
// PETSc and the executable themselves.
#pragma once

#include <mpi.h>

namespace cosim::bench {

struct MemoryUse {
  double peak_bytes = 0;      // sum over ranks of the peak RSS since the baseline was taken
  double baseline_bytes = 0;  // sum over ranks of the RSS when it was taken
};

// Starts a measurement: returns freed heap to the system (glibc), resets this process's peak RSS to its current RSS
// (Linux /proc/self/clear_refs; throws where that is not possible, since getrusage would then report an earlier, larger
// run's peak) and remembers the current RSS.
class PeakMemory {
 public:
  explicit PeakMemory(MPI_Comm comm);
  // Summed over the ranks of comm (collective); valid on every rank.
  MemoryUse total() const;

 private:
  MPI_Comm comm_;
  double baseline_bytes_;
};

}  // namespace cosim::bench
