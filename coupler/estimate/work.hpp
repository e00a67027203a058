// What a scene gives one program to do, as the program itself reports it
// (`cosim-<name> --check scene.yaml --work FILE`): the counts its step's cost and its memory
// grow with, and the bytes one field frame of it adds to the run file.
#pragma once

#include <filesystem>
#include <map>
#include <string>

namespace cosim::estimate {

using Units = std::map<std::string, double>;  // unit name ("cells", "markers", "bodies", "particles") -> count

struct ProgramWork {
  std::string program;     // the section's name
  Units per_step;          // what one step's work grows with
  Units held;              // what the program's memory grows with
  double frame_bytes = 0;  // one field frame in the run file; 0: it writes none
  double state_bytes = 0;  // its checkpoint state (two slots of it are kept)
  double dt = 0;           // where it chooses its own step (the fluid's CFL), its mean step per window; 0: none
  bool grows = false;      // an inflow adds particles as the run goes: the counts are the start's
};

// Reads a work report. Throws std::runtime_error naming the file and what is wrong.
ProgramWork read_work(const std::filesystem::path& file);

}  // namespace cosim::estimate
