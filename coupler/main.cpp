// cosim: the launcher and coupler.
//   cosim check scene.yaml          validate a scene (each program reads its section), show what would run
//   cosim run scene.yaml [-o f.h5]  run it
//   cosim run --resume f.h5         continue a run from its last checkpoint
//   cosim run scene.yaml --target NAME=TOL
//                                   run it at the cheapest resolution whose error in NAME meets
//                                   TOL (docs/study.md)
//   cosim calibrate                 measure this host's costs for the estimates (docs/cost.md)
//   cosim repair f.h5               finish a write a kill cut off, for readers without cosim's
//                                   journal (h5py, ParaView)
//   cosim study scene.yaml --vary KEY=V1,V2,V3 --measure NAME=EXPR
//                                   run the scene at several resolutions: each quantity's value,
//                                   observed order, extrapolate and GCI against the runs' cost
//                                   (docs/study.md)
#include <CLI/CLI.hpp>
#include <fmt/ranges.h>
#include <spdlog/spdlog.h>

#include <iostream>

#include "cosim_git_hash.hpp"
#include "coupler/estimate/calibrate.hpp"
#include "coupler/estimate/estimate.hpp"
#include "coupler/estimate/program_work.hpp"
#include "coupler/launcher/command.hpp"
#include "coupler/output/run_file.hpp"
#include "coupler/run/coupler.hpp"
#include "coupler/scene/error.hpp"
#include "coupler/scene/plan.hpp"
#include "coupler/scene/unused_materials.hpp"
#include "coupler/study/argument_error.hpp"
#include "coupler/study/measures.hpp"
#include "coupler/study/study.hpp"
#include "coupler/target/target.hpp"

namespace {

int check(const std::string& file) {
  const auto scene = cosim::scene::load_scene(file);
  const auto measures = cosim::study::measures_of(scene, {});
  const auto plan = cosim::scene::plan_participants(scene);
  for (const auto& w : cosim::scene::unused_materials(scene)) spdlog::warn("{}", w);
  const auto sections = cosim::estimate::read_sections(scene, plan.start);
  if (!sections.refused.empty()) {
    std::cerr << "cosim: " << cosim::estimate::refused_message(scene, sections.refused) << "\n";
    return 2;
  }
  std::cout << file << ": valid; " << scene.bodies.size() << " bodies, " << scene.windows() << " windows of "
            << scene.coupling.window << " s (" << cosim::scene::to_string(scene.coupling.scheme) << ")\n";
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
  for (const auto& m : measures) std::cout << "  study measure " << m.name << ": " << m.text << "\n";
  std::cout << cosim::estimate::estimate_here(scene, plan.start, sections.work, COSIM_GIT_HASH) << "\n";
  return 0;
}

int repair(const std::string& file) {
  if (cosim::output::RunFile::finish_commit(file))
    std::cout << file << ": finished the write a kill cut off and removed its journal\n";
  else
    std::cout << file << ": no write was cut off; nothing to finish\n";
  return 0;
}

// The command line as a shell would take it back, for the study's report.
std::string command_line(int argc, char** argv) {
  std::string out = "cosim";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool plain = !a.empty() && a.find_first_not_of(
                                         "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                         "0123456789_-+=.,/:") == std::string::npos;
    std::string quoted = "'";
    for (char c : a) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    out += " " + (plain ? a : quoted + "'");
  }
  return out;
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
  cosim::target::Request target_request;
  std::string budget;
  auto* target_opt =
      run_cmd
          ->add_option("--target", target_request.target,
                       "NAME=TOL: run at the cheapest resolution whose error in the measure NAME is within TOL (0.5% "
                       "relative, 1e-4 absolute), chosen from three cheap levels (docs/study.md)")
          ->excludes(resume_opt)
          ->excludes("--output");
  run_cmd
      ->add_option("--measure", target_request.measures,
                   "NAME=EXPR: with --target, a quantity besides the scene's study.measure")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
      ->needs(target_opt);
  run_cmd->add_option("--budget", budget, "With --target: refuse a level estimated to take longer (600, 90s, 10m, 2h)")
      ->needs(target_opt);
  run_cmd
      ->add_option("--ratio", target_request.ratio,
                   "With --target: the refinement ratio between the cheap levels (default 1.5)")
      ->needs(target_opt);
  run_cmd
      ->add_option("--out", target_request.out,
                   "With --target: folder for the levels and the report (default "
                   "runs/target/<scene>)")
      ->needs(target_opt);

  double calibrate_scale = 1;
  auto* calibrate_cmd =
      app.add_subcommand("calibrate", "Measure what runs cost on this host, for the estimate before every run");
  calibrate_cmd->add_option("--scale", calibrate_scale, "Make each calibration run this many times longer")
      ->check(CLI::Range(0.1, 100.0));

  std::string repair_file;
  auto* repair_cmd = app.add_subcommand(
      "repair", "Finish a write a kill cut off (<file>.journal), so that h5py and ParaView read the run file whole");
  repair_cmd->add_option("run_file", repair_file, "Run file (HDF5)")->required();

  cosim::study::Request study_request;
  auto* study_cmd = app.add_subcommand("study", "Run a scene at several resolutions: what accuracy costs in time");
  study_cmd->add_option("scene", study_request.scene, "Scene file (YAML)")->required();
  auto* vary_opt =
      study_cmd
          ->add_option("--vary", study_request.vary,
                       "KEY=V1,V2,...: a dotted key of the scene (coupling.window, bodies.0.position) and its value "
                       "on each level, coarsest first; several --vary change together, level by level")
          ->expected(1)
          ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  study_cmd
      ->add_option("--set", study_request.set,
                   "KEY=VALUE: a key of the scene set to the same value on every level (time.end=1.0, "
                   "participants.fluid.options.bodies={method: staircase})")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  auto* refine_opt = study_cmd
                         ->add_option("--refine", study_request.refine,
                                      "F: instead of --vary, divide coupling.window and every participant's dt by F "
                                      "per level, multiply the fluid's grid cells and the tracker's mesh cells by F "
                                      "and shrink the tolerances the scene writes by F^2 (docs/study.md)")
                         ->excludes(vary_opt);
  study_cmd->add_option("--levels", study_request.levels, "N: levels with --refine (default 3)")->needs(refine_opt);
  study_cmd
      ->add_option("--measure", study_request.measures,
                   "NAME=EXPR: a quantity of each run, such as peak=max(body:ball:velocity.z) (docs/study.md); adds "
                   "to the scene's study.measure")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  study_cmd->add_option("--order", study_request.order,
                        "P: the order the scheme should show, to judge the asymptotic range (default: the scene's "
                        "study.order)");
  study_cmd->add_option("--out", study_request.out,
                        "Folder for the levels and the report (default runs/study/<scene>)");
  study_cmd->add_option("--jobs", study_request.jobs,
                        "N: runs side by side (default 1); runs side by side share the cores, which distorts their "
                        "wall times");

  CLI11_PARSE(app, argc, argv);
  spdlog::set_pattern("cosim: %^%l%$: %v");
  spdlog::set_level(spdlog::level::info);

  return cosim::scene::exit_code("cosim", [&] {
    if (*check_cmd) return check(check_file);
    if (*repair_cmd) return repair(repair_file);
    if (*calibrate_cmd) return cosim::estimate::calibrate(cosim::launcher::own_directory() / "cosim", calibrate_scale);
    if (*study_cmd) {
      study_request.command = command_line(argc, argv);
      try {
        return cosim::study::study(study_request);
      } catch (const cosim::study::ArgumentError& e) {
        std::cerr << "cosim study: " << e.what() << "\n";
        return 2;
      }
    }
    if (!target_request.target.empty()) {
      if (scene_file.empty()) {
        std::cerr << "cosim run: --target needs a scene file\n";
        return 2;
      }
      target_request.scene = scene_file;
      target_request.command = command_line(argc, argv);
      target_request.build = COSIM_GIT_HASH;
      try {
        if (!budget.empty()) target_request.budget = cosim::target::parse_budget(budget);
        return cosim::target::run_to_target(target_request);
      } catch (const cosim::study::ArgumentError& e) {
        std::cerr << "cosim run: " << e.what() << "\n";
        return 2;
      }
    }
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
