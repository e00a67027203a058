// Entries of `bodies:` that make many bodies alike (`generate: lattice | random | file`),
// named from a pattern on their running index. docs/scenes.md has the keys.
#pragma once

#include <filesystem>
#include <span>
#include <vector>

#include "coupler/scene/reader.hpp"
#include "coupler/scene/scene.hpp"

namespace cosim::scene {

struct GeneratorContext {
  Domain domain;
  std::filesystem::path dir;      // the scene's folder, against which `file` is resolved
  std::filesystem::path output;   // the scene's output.file, which a run overwrites
  std::span<const Body> earlier;  // bodies of the entries before: random addition keeps clear of them
};

struct Generated {
  Generator kind;
  std::vector<Body> bodies;  // named, in index order
};

// Reads the entry `r`, one that has `generate`, completely.
Generated generate_bodies(const Reader& r, const GeneratorContext& context);

}  // namespace cosim::scene
