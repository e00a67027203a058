// cosim: the launcher and coupler.
//   cosim check scene.yaml          validate a scene (each program reads its section), show what would run
//   cosim run scene.yaml [-o f.h5]  run it
//   cosim run --resume f.h5         continue a run from its last checkpoint
#include <CLI/CLI.hpp>
#include <fmt/ranges.h>
#include <spdlog/spdlog.h>

#include <iostream>

#include "coupler/launcher/command.hpp"
#include "coupler/launcher/section_check.hpp"
#include "coupler/run/coupler.hpp"
#include "coupler/scene/error.hpp"
#include "coupler/scene/plan.hpp"
#include "coupler/scene/unused_materials.hpp"

namespace {

int check(const std::string& file) {
  const auto scene = cosim::scene::load_scene(file);
  const auto plan = cosim::scene::plan_participants(scene);
  for (const auto& w : cosim::scene::unused_materials(scene)) spdlog::warn("{}", w);
  const auto refused = cosim::launcher::refused_sections(scene, plan.start, cosim::launcher::own_directory());
  if (!refused.empty()) {
    std::cerr << "cosim: invalid scene: " << file << ": " << fmt::format("{}", fmt::join(refused, ", "))
              << (refused.size() > 1 ? " refused their sections" : " refused its section") << " (above)\n";
    return 2;
  }
  std::cout << file << ": valid; " << scene.bodies.size() << " bodies, " << scene.windows()
            << " windows of " << scene.coupling.window << " s ("
            << cosim::scene::to_string(scene.coupling.scheme) << ")\n";
  for (const auto& g : scene.generators) {
    const std::string& first = scene.bodies[g.first].name;
    const std::string& last = scene.bodies[g.first + g.count - 1].name;
    const std::string made = g.count == 1 ? "1 body " + first : fmt::format("{} bodies {} .. {}", g.count, first, last);
    std::cout << fmt::format("  bodies[{}] ({}): {}\n", g.entry, cosim::scene::to_string(g.kind), made);
  }
  for (const auto& p : plan.start) {
    const auto command = cosim::launcher::participant_command(scene, p, cosim::launcher::own_directory());
    std::cout << "  starts " << p.name << " (dt " << p.dt << " s): " << fmt::format("{}", fmt::join(command, " "))
              << "\n";
  }
  for (const auto& s : plan.skipped) std::cout << "  not started: " << s << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"cosim: co-simulation of particulate and rarefied flows"};
  app.require_subcommand(1);

  std::string check_file;
  auto* check_cmd = app.add_subcommand("check", "Validate a scene without running it");
  check_cmd->add_option("scene", check_file, "Scene file (YAML)")->required();

  cosim::run::RunRequest request;
  std::string scene_file, output, resume;
  bool quiet = false;
  auto* run_cmd = app.add_subcommand("run", "Run a scene, or resume a run file");
  auto* scene_opt = run_cmd->add_option("scene", scene_file, "Scene file (YAML)");
  auto* resume_opt = run_cmd->add_option("--resume", resume, "Continue this run file from its last checkpoint");
  run_cmd->add_option("-o,--output", output, "Run file to write (default: the scene's output.file)")
      ->excludes(resume_opt);
  run_cmd->add_flag("-q,--quiet", quiet, "No progress line");
  scene_opt->excludes(resume_opt);

  CLI11_PARSE(app, argc, argv);
  spdlog::set_pattern("cosim: %^%l%$: %v");
  spdlog::set_level(spdlog::level::info);

  return cosim::scene::exit_code("cosim", [&] {
    if (*check_cmd) return check(check_file);
    if (scene_file.empty() && resume.empty()) {
      std::cerr << "cosim run: give a scene file or --resume run.h5\n";
      return 2;
    }
    request.scene = scene_file;
    if (!resume.empty()) request.resume = resume;
    request.output = output;
    request.progress = !quiet;
    return cosim::run::run(request);
  });
}
