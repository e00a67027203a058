// What a scene gives a built-in program to do, as `<program> --check scene.yaml --work FILE`
// writes it for the coupler's cost estimate (coupler/estimate/work.hpp reads it):
//
//   program: fluid        # the section's name
//   per_step:             # what one step's work grows with (whole run, all ranks)
//     cells: 8192
//     markers: 410
//   held:                 # what the program's memory grows with
//     cells: 8192
//     markers: 410
//   frame_bytes: 337520   # what one field frame of it adds to the run file (0: writes none)
//   state_bytes: 466000   # about what its checkpoint state adds, per slot
//   dt: 0.0167            # the step it expects to take, where smaller than the scene's dt
//   grows: true           # only when an inflow adds particles: the counts are the start's
//
// Header-only: the three programs link yaml-cpp through cosim_scene already.
#pragma once

#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace cosim::participant {

// Unit name and count, in the order they are written.
using WorkUnits = std::vector<std::pair<std::string, std::uint64_t>>;

struct WorkReport {
  std::string program;
  WorkUnits per_step;
  WorkUnits held;
  std::uint64_t frame_bytes = 0;
  std::uint64_t state_bytes = 0;  // its checkpoint state, to within a few per cent
  double dt = 0;                  // its expected step where it chooses its own (0: the scene's dt)
  bool grows = false;
};

inline std::string work_yaml(const WorkReport& report) {
  YAML::Emitter out;
  const auto units = [&](const char* key, const WorkUnits& list) {
    out << YAML::Key << key << YAML::Value << YAML::BeginMap;
    for (const auto& [name, count] : list) out << YAML::Key << name << YAML::Value << count;
    out << YAML::EndMap;
  };
  out << YAML::BeginMap;
  out << YAML::Key << "program" << YAML::Value << report.program;
  units("per_step", report.per_step);
  units("held", report.held);
  out << YAML::Key << "frame_bytes" << YAML::Value << report.frame_bytes;
  out << YAML::Key << "state_bytes" << YAML::Value << report.state_bytes;
  if (report.dt > 0) out << YAML::Key << "dt" << YAML::Value << report.dt;
  if (report.grows) out << YAML::Key << "grows" << YAML::Value << true;
  out << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

// Throws std::runtime_error naming the file if it cannot be written.
inline void write_work(const std::filesystem::path& file, const WorkReport& report) {
  std::ofstream out(file);
  out << work_yaml(report);
  out.close();
  if (!out) throw std::runtime_error("cannot write the work report " + file.string());
}

}  // namespace cosim::participant
