// The scene parser knows the keys every program shares; each built-in program owns its
// own section (docs/architecture.md). So that `cosim check` also finds a bad option there, or a mesh
// or species file that cannot be read, it asks each built-in it would start to read its
// section as it does at start-up: `cosim-<name> --check scene.yaml`, one process, no ranks.
// Given a folder, each also writes its work report there as <name>.yaml (`--work`), for the
// cost estimate (coupler/estimate/work.hpp).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "coupler/scene/scene.hpp"

namespace cosim::launcher {

// The participants among `start` whose program refused its section (each printed why on
// stderr, naming file, line, key and value). External participants are not asked: their
// command line is their own.
std::vector<std::string> refused_sections(const scene::Scene& scene, const std::vector<scene::Participant>& start,
                                          const std::filesystem::path& programs_dir,
                                          const std::filesystem::path& work_dir = {});

}  // namespace cosim::launcher
