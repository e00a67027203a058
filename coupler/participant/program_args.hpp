// The command line every program has besides its coupled mode (started by `cosim run`):
//   <program> --standalone scene.yaml [-o run.h5]   the scene without a coupler
//   <program> --check scene.yaml [--work FILE]      read its own section only (`cosim check`),
//                                                   and write the work it gives (work_report.hpp)
// Header-only: each program links CLI11 itself.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace cosim::participant {

struct ProgramArgs {
  std::string standalone, check, output, work;
};

// Exactly one of --standalone and --check is required. `section` names what --check reads.
inline void add_program_args(CLI::App& app, ProgramArgs& args, const std::string& standalone_help,
                             const std::string& section) {
  auto* mode = app.add_option_group("mode");
  mode->add_option("--standalone", args.standalone, standalone_help);
  auto* check = mode->add_option("--check", args.check,
                                 "Read this scene's " + section + " as a run would, and say what is wrong");
  mode->require_option(1);
  app.add_option("--work", args.work,
                 "With --check: write the sizes this scene's cost grows with to this YAML file (for cosim's estimate)")
      ->needs(check);
  app.add_option("-o,--output", args.output, "Run file to write (default: the scene's output.file)");
}

}  // namespace cosim::participant
