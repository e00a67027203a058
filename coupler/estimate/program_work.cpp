#include "coupler/estimate/program_work.hpp"

#include <spdlog/spdlog.h>
#include <stdlib.h>

#include <filesystem>
#include <stdexcept>

#include "coupler/launcher/command.hpp"
#include "coupler/launcher/section_check.hpp"

namespace cosim::estimate {
namespace fs = std::filesystem;

namespace {

// A rank's share of the work: what one rank's seconds and peak memory, which the run
// records, grow with (an even split, as the box decomposition and the grid's make).
ProgramWork one_rank(ProgramWork work, int ranks) {
  if (ranks > 1)
    for (Units* units : {&work.per_step, &work.held})
      for (auto& [unit, count] : *units) count /= ranks;
  return work;
}

}  // namespace

std::string refused_message(const scene::Scene& scene, const std::vector<std::string>& refused) {
  std::string names;
  for (const auto& n : refused) names += (names.empty() ? "" : ", ") + n;
  return "invalid scene: " + scene.file.string() + ": " + names +
         (refused.size() > 1 ? " refused their sections" : " refused its section") + " (above)";
}

SectionsRead read_sections(const scene::Scene& scene, const std::vector<scene::Participant>& start) {
  std::string pattern = (fs::temp_directory_path() / "cosim-work-XXXXXX").string();
  if (mkdtemp(pattern.data()) == nullptr)
    throw std::runtime_error("cannot create a folder in " + fs::temp_directory_path().string());
  const fs::path dir = pattern;
  SectionsRead out;
  try {
    out.refused = launcher::refused_sections(scene, start, launcher::own_directory(), dir);
    for (const auto& p : start) {
      const fs::path report = dir / (p.name + ".yaml");
      if (!fs::exists(report)) continue;
      try {
        out.work[p.name] = one_rank(read_work(report), p.ranks);
      } catch (const std::exception& e) {
        spdlog::warn("{}'s work report is left out of the estimate: {}", p.name, e.what());
      }
    }
  } catch (...) {
    fs::remove_all(dir);
    throw;
  }
  fs::remove_all(dir);
  return out;
}

}  // namespace cosim::estimate
