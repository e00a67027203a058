#include "tests/integration/standalone_run.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <string>
#include <string_view>

#include "coupler/launcher/command.hpp"

namespace cosim::testing {

namespace fs = std::filesystem;

int run_program(const std::string& program, const std::string& arguments, int ranks, const fs::path& log) {
  const auto path = fs::read_symlink("/proc/self/exe").parent_path() / program;
  // The test may be an MPI singleton itself; its program must not think it is part of that
  // job. mpirun gets what cosim would give it.
  std::string command = "env";
  for (char** e = environ; *e != nullptr; ++e) {
    const std::string_view entry(*e);
    const std::string_view key = entry.substr(0, entry.find('='));
    if (launcher::describes_enclosing_mpi_job(key)) command.append(" -u ").append(key);
  }
  if (ranks > 1) {
    for (const auto& [key, value] : launcher::mpi_environment()) command += " " + key + "=" + value;
    command += " mpirun -n " + std::to_string(ranks);
  }
  command += " " + path.string() + " " + arguments + " > " + log.string() + " 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

int run_standalone(const std::string& program, const fs::path& scene, const fs::path& out, int ranks,
                   const fs::path& log) {
  return run_program(program, "--standalone " + scene.string() + " -o " + out.string(), ranks, log);
}

int run_check(const std::string& program, const fs::path& scene, const fs::path& work, const fs::path& log) {
  return run_program(program, "--check " + scene.string() + (work.empty() ? "" : " --work " + work.string()), 1, log);
}

}  // namespace cosim::testing
