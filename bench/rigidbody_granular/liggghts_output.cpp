#include <algorithm>
#include <regex>
#include <sstream>
#include <string>
#include <utility>

#include "bench/rigidbody_granular/liggghts.hpp"

namespace cosim::bench {

std::optional<LiggghtsLog> read_liggghts_log(std::istream& log) {
  LiggghtsLog result;
  const std::regex loop(R"(Loop time of (\S+) on \d+ procs for (\d+) steps with (\d+) atoms)");
  bool thermo = false;  // between the thermo header and the loop time
  bool found = false;
  std::string line;
  while (std::getline(log, line)) {
    if (result.version.empty() && line.rfind("LIGGGHTS", 0) == 0) result.version = line;
    std::smatch m;
    if (std::regex_search(line, m, loop)) {
      result.loop_seconds = std::stod(m[1]);
      result.steps = std::stoi(m[2]);
      result.atoms = std::stoul(m[3]);
      thermo = false;
      found = true;
    } else if (std::string first; std::istringstream(line) >> first && first == "Step") {
      thermo = true;  // the thermo header: Step Atoms and the energies' names, cut to 8 characters
    } else if (thermo) {
      // step atoms translational rotational; anything else (a warning) is skipped
      std::istringstream row(line);
      long step = 0;
      std::size_t atoms = 0;
      double translational = 0;
      double rotational = 0;
      if (row >> step >> atoms >> translational >> rotational)
        result.kinetic_energy.push_back(translational + rotational);
    }
  }
  if (!found) return std::nullopt;
  return result;
}

std::vector<Eigen::Vector3d> read_liggghts_dump(std::istream& dump) {
  std::vector<std::pair<long, Eigen::Vector3d>> atoms;
  std::string line;
  bool rows = false;
  while (std::getline(dump, line)) {
    if (line.rfind("ITEM:", 0) == 0) {
      rows = line.rfind("ITEM: ATOMS", 0) == 0;
      if (rows) atoms.clear();  // a later frame replaces an earlier one
      continue;
    }
    if (!rows) continue;
    std::istringstream row(line);
    long id = 0;
    Eigen::Vector3d x;
    if (row >> id >> x.x() >> x.y() >> x.z()) atoms.emplace_back(id, x);
  }
  std::sort(atoms.begin(), atoms.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<Eigen::Vector3d> centres;
  for (const auto& [id, x] : atoms) centres.push_back(x);
  return centres;
}

}  // namespace cosim::bench
