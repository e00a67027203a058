#include "bench/coupler_roundtrip/summary.hpp"

#include <cstdio>

namespace cosim::bench {
namespace {

std::string case_name(const char* family, const Case& c) {
  return std::string(family) + "/p" + std::to_string(c.participants) + "/n" + std::to_string(c.doubles) + "/" +
         to_string(c.transport);
}

}  // namespace

std::string Summary::window_name(const Case& c) { return case_name("window", c); }
std::string Summary::raw_name(const Case& c) { return case_name("raw", c); }

void Summary::ReportRuns(const std::vector<Run>& runs) {
  // With repetitions the median comes after the single runs and replaces them.
  for (const Run& run : runs) {
    const bool wanted = run.run_type == Run::RT_Iteration || run.aggregate_name == "median";
    const auto it = run.counters.find("items_per_second");
    if (wanted && !run.error_occurred && it != run.counters.end()) rate_[run.run_name.function_name] = it->second.value;
  }
  ConsoleReporter::ReportRuns(runs);
}

void Summary::print_table(const std::vector<Case>& cases) const {
  std::printf(
      "\nOne window = an Advance to every participant carrying its input at the window start\n"
      "and at its end (two arrays of N doubles), a Result back from each with its outputs\n"
      "(N doubles, computed from both inputs into a buffer of its own) and its Stats; all\n"
      "encoded, sent, decoded and validated. Raw = the same scatter/gather to the same number\n"
      "of peers with plain frames of the same payload (two of N doubles out, one back) and\n"
      "the same computation, but no header, no validation, received in place.\n"
      "overhead = raw windows/s / coupler windows/s; GB/s counts the 3N doubles per\n"
      "participant (both directions).\n\n");
  std::printf("%5s %9s %5s %16s %16s %9s %10s %10s\n", "parts", "N", "via", "coupler win/s", "raw win/s", "overhead",
              "cpl GB/s", "raw GB/s");
  for (const Case& c : cases) {
    const auto w = rate_.find(window_name(c));
    const auto r = rate_.find(raw_name(c));
    if (w == rate_.end() || r == rate_.end()) continue;  // filtered out on the command line
    std::printf("%5d %9zu %5s %16.1f %16.1f %8.2fx %10.3f %10.3f\n", c.participants, c.doubles, to_string(c.transport),
                w->second, r->second, r->second / w->second, w->second * window_bytes(c) / 1e9,
                r->second * window_bytes(c) / 1e9);
  }
}

}  // namespace cosim::bench
