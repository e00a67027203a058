// Each built-in program the run starts reads its section and reports its work
// (launcher/section_check.hpp), in a private folder removed afterwards.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "coupler/estimate/work.hpp"
#include "coupler/scene/scene.hpp"

namespace cosim::estimate {

struct SectionsRead {
  std::vector<std::string> refused;         // programs that refused their section (each said why)
  std::map<std::string, ProgramWork> work;  // the others' reports, by participant name
};

// "invalid scene: FILE: fluid refused its section (above)"
std::string refused_message(const scene::Scene& scene, const std::vector<std::string>& refused);

SectionsRead read_sections(const scene::Scene& scene, const std::vector<scene::Participant>& start);

}  // namespace cosim::estimate
