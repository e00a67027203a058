// The study's plots of error against wall time, one PNG per quantity, drawn by
// scripts/study_plot (Python and matplotlib, as the project's other plots).
#pragma once

#include <filesystem>
#include <string>

namespace cosim::study {

// Runs the plot script on results.csv, writing error_<quantity>.png beside it; its output
// goes to plot.log there. Returns "" when it succeeded, otherwise why not.
std::string plot(const std::filesystem::path& csv);

}  // namespace cosim::study
