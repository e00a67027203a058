// The results as a console table (a row as each run ends) and as CSV.
#pragma once

#include <string>
#include <vector>

#include "bench/rigidbody_accuracy/run.hpp"

namespace cosim::bench {

// "soft", "pgs", "si", "jacobi", "dem k=1e+05".
std::string solver_label(const rigidbody::world::Settings& settings);

void print_header();
void print_row(const Run& run);
// Throws std::runtime_error if the file cannot be written.
void write_csv(const std::string& path, const std::vector<Run>& runs);

}  // namespace cosim::bench
