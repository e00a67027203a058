// tracker_study: studies of the tracking against the references (docs/references.md, Tracker),
// one part per source file; --part selects them.
#include <CLI/CLI.hpp>

#include "bench/tracker_study/parts.hpp"

int main(int argc, char** argv) {
  CLI::App app{"Tracking studies against the references"};
  cosim::bench::StudyOptions options;
  std::string part = "all";
  app.add_option("--part", part, "which part to run")->check(CLI::IsMember({"all", "algorithms", "pruning"}));
  bool quick = false, tiny = false;
  auto* quick_flag = app.add_flag("--quick", quick, "small meshes and counts (the ctest)");
  app.add_flag("--tiny", tiny, "smaller still, timed once (the ctest of the sanitizer build)")->excludes(quick_flag);
  app.add_option("--csv", options.csv, "write each part's rows to <csv>_<part>.csv");
  CLI11_PARSE(app, argc, argv);
  options.size = quick ? cosim::bench::Size::quick : tiny ? cosim::bench::Size::tiny : cosim::bench::Size::full;
  int failed = 0;
  if (part == "all" || part == "algorithms") failed |= cosim::bench::algorithms_part(options);
  if (part == "all" || part == "pruning") failed |= cosim::bench::pruning_part(options);
  return failed;
}
