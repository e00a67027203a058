#include "bench/fluid_throughput/memory.hpp"

#include <malloc.h>
#include <sys/resource.h>
#include <unistd.h>

#include <fstream>
#include <stdexcept>

namespace cosim::bench {
namespace {

double resident_bytes() {
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  if (!(statm >> pages >> resident)) throw std::runtime_error("cannot read /proc/self/statm");
  return static_cast<double>(resident) * static_cast<double>(sysconf(_SC_PAGESIZE));
}

double summed(double local, MPI_Comm comm) {
  double total = 0;
  MPI_Allreduce(&local, &total, 1, MPI_DOUBLE, MPI_SUM, comm);
  return total;
}

}  // namespace

PeakMemory::PeakMemory(MPI_Comm comm) : comm_(comm) {
  // Heap an earlier run freed would otherwise count in the baseline and then be reused.
  malloc_trim(0);
  // "5" resets the peak RSS that ru_maxrss reports to the current RSS (proc(5)).
  std::ofstream clear("/proc/self/clear_refs");
  if (!(clear << "5" << std::flush))
    throw std::runtime_error("cannot reset the peak RSS through /proc/self/clear_refs");
  baseline_bytes_ = resident_bytes();
}

MemoryUse PeakMemory::total() const {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return {summed(1024.0 * static_cast<double>(usage.ru_maxrss), comm_), summed(baseline_bytes_, comm_)};
}

}  // namespace cosim::bench
