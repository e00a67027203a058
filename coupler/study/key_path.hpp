// Where `--vary` puts a value: a dotted key path into the scene document
// ("coupling.window", "participants.fluid.options.grid.cells", "bodies.0.position"; a
// number steps into a list).
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>

namespace cosim::study {

// Sets the node at `path` in `root` (a handle: the document changes) to `value`. Every step
// but the last must exist; the last key of a mapping may be new, and the scene loader then
// judges it like any key. Throws ArgumentError starting with `argument`.
void set_at(YAML::Node root, const std::string& path, const YAML::Node& value, const std::string& argument);

}  // namespace cosim::study
