#include "coupler/study/study.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <iostream>

#include "coupler/scene/error.hpp"
#include "coupler/study/argument_error.hpp"
#include "coupler/study/key_path.hpp"
#include "coupler/study/level_runs.hpp"
#include "coupler/study/levels.hpp"
#include "coupler/study/measures.hpp"
#include "coupler/study/report.hpp"

namespace cosim::study {
namespace {

namespace fs = std::filesystem;

std::vector<Varied> varied_of(const Request& request, const scene::Scene& scene) {
  if (request.refine) {
    if (!(*request.refine > 1))
      throw ArgumentError(fmt::format("--refine {}: the factor must be > 1", *request.refine));
    if (request.levels < 2) throw ArgumentError(fmt::format("--levels {}: a study needs at least 2", request.levels));
    return refine(scene, *request.refine, request.levels);
  }
  if (request.vary.empty()) throw ArgumentError("nothing to vary: give --vary KEY=V1,V2,... or --refine F");
  std::vector<Varied> out;
  for (const std::string& argument : request.vary) {
    Varied v = parse_vary(argument);
    for (const Varied& earlier : out)
      if (earlier.key == v.key) throw ArgumentError(fmt::format("{}: {} is varied already", v.argument, v.key));
    out.push_back(std::move(v));
  }
  return out;
}

// The arguments that made the levels, for messages about a level.
std::string arguments_of(const std::vector<Varied>& varied) {
  std::vector<std::string> out;
  for (const Varied& v : varied)
    if (std::find(out.begin(), out.end(), v.argument) == out.end()) out.push_back(v.argument);
  return fmt::format("{}", fmt::join(out, " "));
}

// The scene with every --set applied, as a document and as the scene it loads to.
std::pair<YAML::Node, scene::Scene> with_settings(const Request& request, std::vector<std::string>& shown) {
  scene::Scene scene = scene::load_scene(request.scene);
  YAML::Node document = level_document(scene);
  if (request.set.empty()) return {document, scene};
  for (const std::string& argument : request.set) {
    const Setting s = parse_set(argument);
    set_at(document, s.key, s.value, s.argument);
    shown.push_back(s.key + " = " + text(s.value));
  }
  YAML::Emitter out;
  out << document;
  try {
    scene = scene::load_scene_from_string(out.c_str(), request.scene);
  } catch (const scene::SceneError& e) {
    throw ArgumentError(
        fmt::format("--set {}: the scene is no longer valid: {}", fmt::join(request.set, " --set "), e.what()));
  }
  return {document, scene};
}

}  // namespace

int study(const Request& request) {
  std::vector<std::string> settings;
  const auto [document, scene] = with_settings(request, settings);
  const std::vector<Measure> measures = measures_of(scene, request.measures);
  if (measures.empty())
    throw ArgumentError("nothing to measure: give --measure NAME=EXPRESSION, or the scene's study.measure");
  const std::vector<Varied> varied = varied_of(request, scene);
  const std::size_t n = level_count(varied);
  if (request.jobs < 1) throw ArgumentError(fmt::format("--jobs {}: at least 1", request.jobs));

  Results r;
  r.scene = request.scene;
  r.command = request.command;
  for (const Varied& v : varied) r.keys.push_back(v.key);
  r.set = settings;
  r.ratios = refinement_ratios(varied.front());
  r.expected_order = request.order ? request.order : scene.study.order;
  r.jobs = request.jobs;

  const fs::path dir = request.out.empty() ? fs::path("runs/study") / request.scene.stem() : request.out;
  fs::create_directories(dir);
  const std::string arguments = arguments_of(varied);
  for (std::size_t k = 0; k < n; ++k) r.levels.push_back(write_level(dir, document, varied, k, measures, arguments));
  const bool failed = !run_levels(r.levels, 0, r.keys, request.jobs, "cosim study");

  for (const Measure& m : measures) r.quantities.push_back(measure_quantity(m, r));
  const fs::path csv = dir / "results.csv";
  write_csv(r, csv);
  write_costs_csv(r, dir / "costs.csv");
  set_plots(r, csv);
  write_report(r, dir / "report.md");
  std::cout << quantity_sections(r, false) << costs_section(r)
            << fmt::format("\nwrote {}, {}, {} and the plots beside them\n", (dir / "report.md").string(), csv.string(),
                           (dir / "costs.csv").string());
  return failed ? 1 : 0;
}

}  // namespace cosim::study
