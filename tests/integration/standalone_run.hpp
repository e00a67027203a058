// Runs a real solver program (next to the test binary) with --standalone or --check.
#pragma once

#include <filesystem>
#include <string>

namespace cosim::testing {

// Its exit code, or -1 if it did not exit normally. Output (stdout and stderr) goes to `log`.
// ranks > 1: under `mpirun -n ranks`, with the environment cosim's launcher gives it.
int run_standalone(const std::string& program, const std::filesystem::path& scene, const std::filesystem::path& out,
                   int ranks = 1, const std::filesystem::path& log = "/dev/null");

// `program arguments` (split by the shell); as run_standalone().
int run_program(const std::string& program, const std::string& arguments, int ranks = 1,
                const std::filesystem::path& log = "/dev/null");

// `program --check scene`, with `--work work` unless `work` is empty; as run_standalone().
int run_check(const std::string& program, const std::filesystem::path& scene, const std::filesystem::path& work,
              const std::filesystem::path& log = "/dev/null");

}  // namespace cosim::testing
