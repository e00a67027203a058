#include "coupler/study/plot.hpp"

#include <unistd.h>

#include "coupler/study/runner.hpp"

namespace cosim::study {

std::string plot(const std::filesystem::path& csv) {
  // The script is the source tree's (a compile definition); an installed cosim without the
  // source tree writes its report without plots.
  const std::filesystem::path script = COSIM_STUDY_PLOT;
  if (access(script.c_str(), X_OK) != 0) return script.string() + " is not there to run";
  const auto log = csv.parent_path() / "plot.log";
  try {
    const Usage u = run_all({{{script.string(), csv.string()}, log}}, 1, {}, {}).front();
    if (!u.ended.empty()) return script.filename().string() + " " + u.ended + " (see " + log.filename().string() + ")";
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

}  // namespace cosim::study
