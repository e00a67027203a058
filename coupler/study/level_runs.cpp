#include "coupler/study/level_runs.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <fstream>
#include <iostream>
#include <stdexcept>

#include "coupler/launcher/command.hpp"
#include "coupler/launcher/section_check.hpp"
#include "coupler/scene/error.hpp"
#include "coupler/scene/plan.hpp"
#include "coupler/study/argument_error.hpp"
#include "coupler/study/measures.hpp"
#include "coupler/study/plot.hpp"
#include "coupler/study/runner.hpp"
#include "coupler/study/verdict.hpp"

namespace cosim::study {
namespace {

namespace fs = std::filesystem;

void write_variant(const YAML::Node& document, const std::vector<Varied>& varied, std::size_t level, const Level& l) {
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
void check_level(const Level& l, std::size_t level, const std::vector<Measure>& measures,
                 const std::string& arguments) {
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

}  // namespace

YAML::Node level_document(const scene::Scene& scene) {
  YAML::Node document = YAML::Load(scene.text);
  // A scene in the working folder has an empty folder, which fs::absolute refuses.
  const fs::path folder = scene.folder.empty() ? fs::path(".") : scene.folder;
  document["folder"] = fs::absolute(folder).lexically_normal().string();
  return document;
}

Level write_level(const fs::path& dir, const YAML::Node& document, const std::vector<Varied>& varied, std::size_t k,
                  const std::vector<Measure>& measures, const std::string& arguments) {
  Level l;
  const std::string stem = fmt::format("level_{}", k + 1);
  l.scene = dir / (stem + ".yaml");
  l.run_file = dir / (stem + ".h5");
  l.log = dir / (stem + ".log");
  for (const Varied& v : varied) l.values.push_back(text(v.values[k]));
  write_variant(document, varied, k, l);
  check_level(l, k, measures, arguments);
  return l;
}

bool run_levels(std::vector<Level>& levels, std::size_t first, const std::vector<std::string>& keys, int jobs,
                const std::string& who) {
  const std::string self = fs::read_symlink("/proc/self/exe").string();
  const std::size_t n = levels.size();
  std::vector<Job> runs;
  for (std::size_t k = first; k < n; ++k)
    runs.push_back({{self, "run", levels[k].scene.string(), "-o", levels[k].run_file.string(), "-q"}, levels[k].log});
  const auto started = [&](std::size_t j) {
    const std::size_t k = first + j;
    std::vector<std::string> set;
    for (std::size_t i = 0; i < keys.size(); ++i) set.push_back(keys[i] + " = " + levels[k].values[i]);
    std::cout << fmt::format("{}: level {}/{} running ({})", who, k + 1, n, fmt::join(set, ", ")) << std::endl;
  };
  const auto finished = [&](std::size_t j, const Usage& u) {
    const std::size_t k = first + j;
    if (u.ended.empty())
      std::cout << fmt::format("{}: level {}/{} done: {:.2f} s wall, {:.2f} s CPU, {:.0f} MB peak", who, k + 1, n,
                               u.wall_seconds, u.cpu_seconds, u.peak_mb)
                << std::endl;
    else
      std::cout << fmt::format("{}: level {}/{} failed: cosim run {} (see {})", who, k + 1, n, u.ended,
                               levels[k].log.string())
                << std::endl;
  };
  const std::vector<Usage> usage = run_all(runs, jobs, started, finished);
  bool ok = true;
  for (std::size_t j = 0; j < usage.size(); ++j) {
    Level& l = levels[first + j];
    l.usage = usage[j];
    ok = ok && usage[j].ended.empty();
    if (!usage[j].ended.empty()) continue;
    try {
      l.programs = output::program_costs(l.run_file, scene::is_serial(scene::load_scene(l.scene).coupling.scheme));
    } catch (const std::exception& e) {
      std::cout << fmt::format("{}: level {}: no cost per program: {}", who, first + j + 1, e.what()) << std::endl;
    }
  }
  return ok;
}

Quantity measure_quantity(const Measure& m, const Results& r) {
  const std::size_t n = r.levels.size();
  Quantity q{m,
             std::vector<std::optional<double>>(n),
             std::vector<std::string>(n),
             std::vector<std::optional<Estimate>>(n),
             {},
             false,
             {},
             {}};
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
        q.estimates[k] =
            estimate(*q.values[k], *q.values[k - 1], *q.values[k - 2], r.ratios.r[k - 1], r.ratios.r[k - 2]);
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

}  // namespace cosim::study
