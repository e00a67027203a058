// The poured-spheres scene as a LIGGGHTS run: the files the bench writes for it
// (liggghts_deck.cpp) and what it reads back from LIGGGHTS's output (liggghts_output.cpp).
#pragma once

#include <cstddef>
#include <filesystem>
#include <istream>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "bench/rigidbody_granular/pour.hpp"

namespace cosim::bench {

// The spheres at their start (LIGGGHTS's read_data format, atom_style granular): the
// same positions and velocities as the other engines get, not LIGGGHTS's own insertion.
void write_liggghts_data(const PourScene& scene, const std::filesystem::path& file);

// An input deck that reads `data_file`, runs `steps` steps of scene.dem_dt with thermo
// output of the kinetic energy every `thermo_every` steps, and writes the final x y z
// radius to `dump_file`. Paths are written as given (LIGGGHTS resolves them in its
// working directory).
std::string liggghts_deck(const PourScene& scene, int steps, int thermo_every, const std::string& data_file,
                          const std::string& dump_file);

struct LiggghtsLog {
  std::string version;      // the banner's first line
  double loop_seconds = 0;  // "Loop time of X on 1 procs for N steps with M atoms"
  int steps = 0;
  std::size_t atoms = 0;
  std::vector<double> kinetic_energy;  // translational + rotational, one per thermo line [J]
};

// Reads the screen output of a deck from liggghts_deck; nullopt if it has no loop time.
std::optional<LiggghtsLog> read_liggghts_log(std::istream& log);

// The centres in a custom dump with columns id x y z radius, ordered by id (the last
// frame if there are several).
std::vector<Eigen::Vector3d> read_liggghts_dump(std::istream& dump);

}  // namespace cosim::bench
