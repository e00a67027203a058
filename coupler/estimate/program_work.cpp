#include "coupler/estimate/program_work.hpp"

#include <stdlib.h>

#include <filesystem>
#include <stdexcept>

#include "coupler/launcher/command.hpp"
#include "coupler/launcher/section_check.hpp"

namespace cosim::estimate {
namespace fs = std::filesystem;

std::string refused_message(const scene::Scene& scene, const std::vector<std::string>& refused) {
  std::string names;
  for (const auto& n : refused) names += (names.empty() ? "" : ", ") + n;
  return "invalid scene: " + scene.file.string() + ": " + names +
         (refused.size() > 1 ? " refused their sections" : " refused its section") + " (above)";
}

SectionsRead read_sections(const scene::Scene& scene, const std::vector<scene::Participant>& start) {
  std::string pattern = (fs::temp_directory_path() / "cosim-work-XXXXXX").string();
  if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("cannot create a folder in " + fs::temp_directory_path().string());
  const fs::path dir = pattern;
  SectionsRead out;
  try {
    out.refused = launcher::refused_sections(scene, start, launcher::own_directory(), dir);
    for (const auto& p : start)
      if (fs::exists(dir / (p.name + ".yaml"))) out.work[p.name] = read_work(dir / (p.name + ".yaml"));
  } catch (...) {
    fs::remove_all(dir);
    throw;
  }
  fs::remove_all(dir);
  return out;
}

}  // namespace cosim::estimate
