// /checkpoint: what a resumed run starts from.
//   attrs window (the next window), time; datasets poses (b x 13), forces (b x 6);
//   participants/<name>/state (1-d float64, any length, absent if the participant gave none)
#pragma once

#include <hdf5.h>

#include <optional>
#include <string>
#include <vector>

#include "output/run_file.hpp"

namespace cosim::output {

// Writes c as /checkpoint_new and flushes, then swaps it for /checkpoint and flushes again:
// a failure or a kill while the bulk is written leaves the previous checkpoint in place,
// and the swap itself is a small metadata change.
void write_checkpoint(hid_t file, const Checkpoint& c, std::size_t bodies,
                      const std::vector<std::string>& participants);
// nullopt if the file has no /checkpoint.
std::optional<Checkpoint> read_checkpoint(hid_t file, const std::vector<std::string>& participants);

}  // namespace cosim::output
