#include "standalone_run.hpp"

#include <sys/wait.h>

#include <cstdlib>

namespace cosim::testing {

namespace fs = std::filesystem;

int run_standalone(const std::string& program, const fs::path& scene, const fs::path& out) {
  const auto path = fs::read_symlink("/proc/self/exe").parent_path() / program;
  const auto command = path.string() + " --standalone " + scene.string() + " -o " + out.string() + " > /dev/null 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace cosim::testing
