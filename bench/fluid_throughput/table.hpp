// The throughput table: one row per solver run, on rank 0 (PetscPrintf) and as CSV.
#pragma once

#include <string>
#include <vector>

#include "bench/fluid_throughput/cavity.hpp"

namespace cosim::bench {

void print_header();
void print_row(const ThroughputRun& r);
void write_csv(const std::string& path, const std::vector<ThroughputRun>& runs);

}  // namespace cosim::bench
