// What a study leaves: report.md (a table per quantity and what its levels say),
// results.csv (a row per quantity and level) and the same tables on stdout.
#pragma once

#include <filesystem>
#include <string>

#include "coupler/study/study.hpp"

namespace cosim::study {

// Columns: quantity, expression, level, each varied key, value, error (against the
// extrapolate, or the finest value when there is none), p, extrapolate and gci (from the
// level and the two before it), wall_s, cpu_s, peak_mb.
void write_csv(const Results& results, const std::filesystem::path& file);

// A section per quantity: its table, its findings and, with `plots`, its plot (Markdown).
std::string quantity_sections(const Results& results, bool plots);

void write_report(const Results& results, const std::filesystem::path& file);

}  // namespace cosim::study
