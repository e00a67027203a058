// What a study leaves: report.md (a table per quantity and what its levels say, and what
// each level's programs took), results.csv (a row per quantity and level), costs.csv (a row
// per level and program) and the quantities' tables on stdout.
#pragma once

#include <filesystem>
#include <string>

#include "coupler/study/study.hpp"

namespace cosim::study {

// Columns: quantity, expression, level, each varied key, value, error (against the
// extrapolate, or the finest value when there is none), p, extrapolate and gci (from the
// level and the two before it), wall_s, cpu_s, peak_mb.
void write_csv(const Results& results, const std::filesystem::path& file);

// Columns: level, program (each participant, then "coupler"), share (of the windows' wall
// time), peak_mb (empty for the coupler, and where the run file has none).
void write_costs_csv(const Results& results, const std::filesystem::path& file);

// A section per quantity: its table, its findings and, with `plots`, its plot (Markdown).
std::string quantity_sections(const Results& results, bool plots);

// A table of what each level's programs took: their shares of the wall time and their
// peak memory (Markdown).
std::string costs_section(const Results& results);

void write_report(const Results& results, const std::filesystem::path& file);

}  // namespace cosim::study
