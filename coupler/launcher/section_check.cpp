#include "coupler/launcher/section_check.hpp"

#include <chrono>
#include <iostream>

#include "coupler/launcher/command.hpp"
#include "coupler/launcher/process.hpp"
#include "coupler/scene/plan.hpp"

namespace cosim::launcher {

std::vector<std::string> refused_sections(const scene::Scene& scene, const std::vector<scene::Participant>& start,
                                          const std::filesystem::path& programs_dir,
                                          const std::filesystem::path& work_dir) {
  std::vector<std::string> refused;
  for (const scene::Participant& p : start) {
    if (!p.command.empty() || !scene::is_builtin(p.name)) continue;
    scene::Participant alone = p;
    alone.ranks = 1;  // reading the section takes one process whatever the run's ranks, here
    alone.placement = {};
    auto argv = participant_command(scene, alone, programs_dir);
    argv.insert(argv.end(), {"--check", scene.file.string()});
    if (!work_dir.empty()) argv.insert(argv.end(), {"--work", (work_dir / (p.name + ".yaml")).string()});
    Process program(p.name, argv, mpi_environment());
    program.stop(std::chrono::milliseconds(static_cast<long>(scene.coupling.timeout * 1000)));
    if (program.exit_status() == 0) continue;
    // A program that refuses says why itself; one that did not end would leave no word.
    if (!program.exit_status())
      std::cerr << "cosim: " << argv.front() << " --check: " << program.poll().value_or("did not end")
                << " (given coupling.timeout = " << scene.coupling.timeout << " s to read its section)\n";
    refused.push_back(p.name);
  }
  return refused;
}

}  // namespace cosim::launcher
