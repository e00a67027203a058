// What each program of a run took, from its run file: what `cosim study` reports per level.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace cosim::output {

struct ProgramCost {
  std::string name;        // a participant's, or "coupler"
  double share = 0;        // of the windows' wall time
  double peak_bytes = -1;  // its largest process's peak resident set; -1: not recorded
};

// Each participant's share of the written windows' wall time (the sum of
// /coupling/participants/<name>/wall_seconds over that of /coupling/wall_seconds) and its
// attribute peak_bytes, in the file's participant order, then the coupler's share: what is
// left of each window once its participants' seconds are taken out, one after another where
// `serial` (the serial schemes) and side by side otherwise (the longest of them). The file
// keeps no roles, so this is approximate where some participants work at once in a serial
// scheme (two force providers: counted one after the other, the coupler's share understated)
// or iterate in a parallel one (each one's iterations summed before the longest is taken,
// the coupler's share overstated). Throws std::runtime_error naming the file and object if
// it is not a run file.
std::vector<ProgramCost> program_costs(const std::filesystem::path& path, bool serial);

}  // namespace cosim::output
