#include "coupler/study/study.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <fstream>
#include <iostream>
#include <stdexcept>

#include "coupler/launcher/command.hpp"
#include "coupler/launcher/section_check.hpp"
#include "coupler/scene/error.hpp"
#include "coupler/scene/plan.hpp"
#include "coupler/study/argument_error.hpp"
#include "coupler/study/levels.hpp"
#include "coupler/study/measures.hpp"
#include "coupler/study/plot.hpp"
#include "coupler/study/report.hpp"
#include "coupler/study/verdict.hpp"

namespace cosim::study {
namespace {

namespace fs = std::filesystem;

std::vector<Varied> varied_of(const Request& request, const scene::Scene& scene) {
  if (request.refine) {
    if (!(*request.refine > 1)) throw ArgumentError(fmt::format("--refine {}: the factor must be > 1", *request.refine));
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

void write_variant(const YAML::Node& document, const std::vector<Varied>& varied, std::size_t level,
                   const Level& l) {
  std::vector<std::string> set;
  for (std::size_t i = 0; i < varied.size(); ++i) set.push_back(varied[i].key + " = " + l.values[i]);
  YAML::Emitter out;
  out << YAML::Comment(fmt::format("level {} of cosim study: {}", level + 1, fmt::join(set, ", "))) << YAML::Newline
      << variant(document, varied, level);
  std::ofstream file(l.scene);
  file << out.c_str() << "\n";
  if (!file) throw std::runtime_error("cannot write " + l.scene.string());
}

// Everything `cosim check` finds wrong with a level, before any level runs.
void check_level(const Level& l, std::size_t level, const std::vector<Measure>& measures, const std::string& arguments) {
  scene::Scene s;
  try {
    s = scene::load_scene(l.scene);
  } catch (const scene::SceneError& e) {
    throw ArgumentError(fmt::format("{}: level {} is not a valid scene: {}", arguments, level + 1, e.what()));
  }
  for (const Measure& m : measures)
    if (const std::string why = mismatch(m, s); !why.empty())
      throw ArgumentError(fmt::format("{}: measure {} on level {}: {}", arguments, m.name, level + 1, why));
  const auto refused = launcher::refused_sections(s, scene::plan_participants(s).start, launcher::own_directory());
  if (!refused.empty())
    throw ArgumentError(fmt::format("{}: on level {} ({}), {} refused {} section (above)", arguments, level + 1,
                                    l.scene.string(), fmt::join(refused, ", "), refused.size() > 1 ? "their" : "its"));
}

Quantity measure(const Measure& m, const Results& r) {
  const std::size_t n = r.levels.size();
  Quantity q{m, std::vector<std::optional<double>>(n), std::vector<std::string>(n),
             std::vector<std::optional<Estimate>>(n), {}, false, {}, {}};
  for (std::size_t k = 0; k < n; ++k) {
    if (!r.levels[k].usage.ended.empty()) {
      q.problems[k] = "the run failed";
      continue;
    }
    try {
      q.values[k] = evaluate(m.expression, r.levels[k].run_file);
    } catch (const std::exception& e) {
      q.problems[k] = e.what();
    }
  }
  // Level k with the two before it: phi1 the finest, as in Celik et al.
  if (!r.ratios.r.empty())
    for (std::size_t k = 2; k < n; ++k)
      if (q.values[k] && q.values[k - 1] && q.values[k - 2])
        q.estimates[k] = estimate(*q.values[k], *q.values[k - 1], *q.values[k - 2], r.ratios.r[k - 1], r.ratios.r[k - 2]);
  const auto& last = q.estimates[n - 1];
  if (last && last->order) {
    q.reference = last->extrapolate;
    q.against_extrapolate = true;
  } else {
    q.reference = q.values[n - 1];
  }
  if (r.ratios.r.empty())
    q.finding = "no order: " + r.ratios.why_none + ".";
  else if (last) {
    const auto previous = n >= 4 && q.estimates[n - 2] ? q.estimates[n - 2]->order : std::nullopt;
    q.finding = verdict(*last, r.expected_order, previous);
  } else if (n > 2)
    q.finding = fmt::format("no order: the finest three levels do not all have a value.");
  return q;
}

void set_plots(Results& r, const fs::path& csv) {
  const std::string why = plot(csv);
  for (Quantity& q : r.quantities) {
    const fs::path png = csv.parent_path() / ("error_" + q.measure.name + ".png");
    if (why.empty() && fs::exists(png))
      q.plot = fmt::format("![{}: error against wall time]({})", q.measure.name, png.filename().string());
    else
      q.plot = "No plot: " + (why.empty() ? "the plot script wrote no " + png.filename().string() : why) + ".";
  }
}

}  // namespace

int study(const Request& request) {
  const scene::Scene scene = scene::load_scene(request.scene);
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
  r.ratios = refinement_ratios(varied.front());
  r.expected_order = request.order ? request.order : scene.study.order;
  r.jobs = request.jobs;

  const fs::path dir = request.out.empty() ? fs::path("runs/study") / request.scene.stem() : request.out;
  fs::create_directories(dir);
  const YAML::Node document = YAML::Load(scene.text);
  const std::string arguments = arguments_of(varied);
  const std::string self = fs::read_symlink("/proc/self/exe").string();
  std::vector<Job> jobs;
  for (std::size_t k = 0; k < n; ++k) {
    Level l;
    const std::string stem = fmt::format("level_{}", k + 1);
    l.scene = dir / (stem + ".yaml");
    l.run_file = dir / (stem + ".h5");
    l.log = dir / (stem + ".log");
    for (const Varied& v : varied) l.values.push_back(text(v.values[k]));
    write_variant(document, varied, k, l);
    check_level(l, k, measures, arguments);
    jobs.push_back({{self, "run", l.scene.string(), "-o", l.run_file.string(), "-q"}, l.log});
    r.levels.push_back(std::move(l));
  }

  const auto started = [&](std::size_t k) {
    std::vector<std::string> set;
    for (std::size_t i = 0; i < varied.size(); ++i) set.push_back(varied[i].key + " = " + r.levels[k].values[i]);
    std::cout << fmt::format("cosim study: level {}/{} running ({})", k + 1, n, fmt::join(set, ", ")) << std::endl;
  };
  const auto finished = [&](std::size_t k, const Usage& u) {
    if (u.ended.empty())
      std::cout << fmt::format("cosim study: level {}/{} done: {:.2f} s wall, {:.2f} s CPU, {:.0f} MB peak", k + 1, n,
                               u.wall_seconds, u.cpu_seconds, u.peak_mb)
                << std::endl;
    else
      std::cout << fmt::format("cosim study: level {}/{} failed: cosim run {} (see {})", k + 1, n, u.ended,
                               r.levels[k].log.string())
                << std::endl;
  };
  const std::vector<Usage> usage = run_all(jobs, request.jobs, started, finished);
  bool failed = false;
  for (std::size_t k = 0; k < n; ++k) {
    r.levels[k].usage = usage[k];
    failed = failed || !usage[k].ended.empty();
  }

  for (const Measure& m : measures) r.quantities.push_back(measure(m, r));
  const fs::path csv = dir / "results.csv";
  write_csv(r, csv);
  set_plots(r, csv);
  write_report(r, dir / "report.md");
  std::cout << quantity_sections(r, false) << fmt::format("\nwrote {}, {} and the plots beside them\n",
                                                          (dir / "report.md").string(), csv.string());
  return failed ? 1 : 0;
}

}  // namespace cosim::study
