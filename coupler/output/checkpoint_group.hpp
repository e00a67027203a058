// /checkpoint: what a resumed run starts from, in two slots a and b (layout in run_file.hpp)
// so that writing one never touches the other and never frees file space.
#pragma once

#include <hdf5.h>

#include <optional>
#include <string>
#include <vector>

#include "coupler/output/run_file.hpp"

namespace cosim::output {

// Writes c into the slot `current` does not name and flushes, then points `current` at it
// (an in-place overwrite of one attribute) and flushes again. A failure or a kill before
// the second flush leaves the previous checkpoint current and intact; nothing is deleted or
// shrunk, so HDF5 never truncates the file (see run_file.hpp).
void write_checkpoint(hid_t file, const Checkpoint& c, std::size_t bodies,
                      const std::vector<std::string>& participants);
// The slot `current` names; nullopt if no checkpoint was completed.
std::optional<Checkpoint> read_checkpoint(hid_t file, const std::vector<std::string>& participants);

}  // namespace cosim::output
