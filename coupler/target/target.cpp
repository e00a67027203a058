#include "coupler/target/target.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>

#include "coupler/estimate/estimate.hpp"
#include "coupler/estimate/program_work.hpp"
#include "coupler/scene/plan.hpp"
#include "coupler/study/argument_error.hpp"
#include "coupler/study/level_runs.hpp"
#include "coupler/study/levels.hpp"
#include "coupler/study/measures.hpp"
#include "coupler/study/refinement.hpp"
#include "coupler/study/report.hpp"
#include "coupler/study/verdict.hpp"
#include "coupler/target/error_model.hpp"

namespace cosim::target {
namespace {

namespace fs = std::filesystem;
using study::ArgumentError;

constexpr const char* kWho = "cosim run --target";
constexpr std::size_t kCheap = 3;
constexpr double kSmallestRatio = 1.3;  // cheap levels: the scene coarsened twice, once, and as written

struct Target {
  std::string name;
  Tolerance tolerance;
};

Target parse_target(const std::string& argument) {
  const std::size_t eq = argument.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == argument.size())
    throw ArgumentError(fmt::format("--target {}: expected NAME=TOLERANCE (drag=0.5%, x1=1e-6)", argument));
  try {
    return {argument.substr(0, eq), parse_tolerance(argument.substr(eq + 1))};
  } catch (const std::invalid_argument& e) {
    throw ArgumentError(fmt::format("--target {}: {}", argument, e.what()));
  }
}

study::Measure measure_named(const scene::Scene& scene, const Request& request, const std::string& name) {
  const std::vector<study::Measure> measures = study::measures_of(scene, request.measures);
  for (const study::Measure& m : measures)
    if (m.name == name) return m;
  std::vector<std::string> names;
  for (const study::Measure& m : measures) names.push_back(m.name);
  throw ArgumentError(fmt::format(
      "--target {}: no measure {} ({}); give --measure {}=EXPRESSION", request.target, name,
      names.empty() ? "the scene has no study.measure" : fmt::format("the measures are {}", fmt::join(names, ", ")),
      name));
}

// The bytes the host could give a run now: MemAvailable of /proc/meminfo, 0 if unknown.
double available_bytes() {
  std::ifstream in("/proc/meminfo");
  std::string key, unit;
  double kb = 0;
  while (in >> key >> kb >> unit)
    if (key == "MemAvailable:") return kb * 1024;
  return 0;
}

std::string seconds_text(double s) {
  return s < 120    ? fmt::format("{:.1f} s", s)
         : s < 7200 ? fmt::format("{:.1f} min", s / 60)
                    : fmt::format("{:.1f} h", s / 3600);
}

// The level's values, for a line about it: "window 0.0025, cells [40, 40, 64]".
std::string level_text(const study::Results& r, std::size_t k) {
  std::vector<std::string> set;
  for (std::size_t i = 0; i < r.keys.size(); ++i) set.push_back(r.keys[i] + " = " + r.levels[k].values[i]);
  return fmt::format("{}", fmt::join(set, ", "));
}

// What --target found, said on stdout and appended to the report.
class Story {
 public:
  void say(const std::string& line) {
    std::cout << kWho << ": " << line << std::endl;
    lines_.push_back(line);
  }
  void write(const study::Results& r, const fs::path& dir, const std::string& heading) const {
    const fs::path csv = dir / "results.csv";
    study::write_csv(r, csv);
    study::Results plotted = r;
    study::set_plots(plotted, csv);
    study::write_report(plotted, dir / "report.md");
    std::ofstream out(dir / "report.md", std::ios::app);
    out << "\n## " << heading << "\n\n";
    for (const std::string& l : lines_) out << "- " << l << "\n";
    std::cout << kWho << ": wrote " << (dir / "report.md").string() << "\n";
  }

 private:
  std::vector<std::string> lines_;
};

struct Cost {
  estimate::Estimate estimate;
  double memory_bytes = 0;  // every process of every program
};

Cost cost_of(const study::Level& level, const std::string& build) {
  const scene::Scene s = scene::load_scene(level.scene);
  const auto plan = scene::plan_participants(s);
  const auto sections = estimate::read_sections(s, plan.start);
  if (!sections.refused.empty()) throw ArgumentError(estimate::refused_message(s, sections.refused));
  Cost c{estimate::estimate(s, plan.start, sections.work,
                            estimate::CostStore::load(estimate::CostStore::default_path()), build),
         0};
  for (const auto& p : c.estimate.programs) {
    const scene::Participant* participant = s.participant(p.name);
    c.memory_bytes += p.peak_bytes * (participant != nullptr ? participant->ranks : 1);
  }
  return c;
}

}  // namespace

double parse_budget(const std::string& text) {
  const auto q = number_and_unit(text);
  const std::string unit = q ? q->unit : "";
  const double factor = unit.empty() || unit == "s" ? 1 : unit == "m" || unit == "min" ? 60 : unit == "h" ? 3600 : 0;
  if (!q || factor == 0 || !(q->value > 0))
    throw ArgumentError(fmt::format("--budget {}: expected a time such as 600, 90s, 10m or 2h", text));
  return q->value * factor;
}

int run_to_target(const Request& request) {
  const Target target = parse_target(request.target);
  const scene::Scene scene = scene::load_scene(request.scene);
  const study::Measure measure = measure_named(scene, request, target.name);
  if (!(request.ratio > 1)) throw ArgumentError(fmt::format("--ratio {}: must be > 1", request.ratio));
  const std::string argument = "--target " + request.target;
  const double r = request.ratio;
  const auto scales_for = [&](std::vector<double> scales) { return study::scaled(scene, scales, argument); };
  std::vector<study::Varied> varied = scales_for({1 / (r * r), 1 / r, 1});

  study::Results results;
  results.scene = request.scene;
  results.command = request.command;
  for (const study::Varied& v : varied) results.keys.push_back(v.key);
  results.expected_order = scene.study.order;
  const fs::path dir = request.out.empty() ? fs::path("runs/target") / request.scene.stem() : request.out;
  fs::create_directories(dir);
  const YAML::Node document = study::level_document(scene);
  for (std::size_t k = 0; k < kCheap; ++k)
    results.levels.push_back(study::write_level(dir, document, varied, k, {measure}, argument));
  const std::vector<double> cheap_scales = study::scales_of(scene, varied);
  if (!(cheap_scales[0] < cheap_scales[1] && cheap_scales[1] < cheap_scales[2]))
    throw ArgumentError(
        fmt::format("{}: the scene's {} windows are too few to coarsen by {} twice", argument, scene.windows(), r));

  Story story;
  const std::string heading = fmt::format("Target: {} within {}", target.name, target.tolerance.text);
  const auto measured = [&] {
    results.ratios = study::refinement_ratios(varied.front());
    results.quantities = {study::measure_quantity(measure, results)};
    return results.quantities.front();
  };
  if (!study::run_levels(results.levels, 0, results.keys, 1, kWho)) {
    story.say("a cheap level failed, so there is nothing to fit");
    measured();
    story.write(results, dir, heading);
    return 1;
  }
  const study::Quantity cheap = measured();
  const auto& e = cheap.estimates[kCheap - 1];
  const Fit fit =
      e ? predict(*e, *cheap.values[kCheap - 1], 1, target.tolerance) : Fit{std::nullopt, "a level has no value"};
  if (!fit.prediction) {
    story.say(fmt::format("no level can be chosen: {}. `cosim study` over finer levels shows where convergence sets in",
                          fit.why_none));
    story.write(results, dir, heading);
    return 1;
  }
  const Prediction& p = *fit.prediction;
  story.say(
      fmt::format("the three cheap levels give order {:.3g} and extrapolate {:.8g}; the tolerance is {:.3g} in "
                  "{}'s unit; the scene as written is modelled {:.3g} off (x {} safety: {:.3g})",
                  p.order, p.extrapolate, p.tolerance, target.name, p.finest_error, kSafety, kSafety * p.finest_error));
  if (scene.study.order && std::abs(p.order - *scene.study.order) > study::kOrderTolerance * *scene.study.order)
    story.say(
        fmt::format("the observed order {:.3g} is not the scene's study.order {:g}: the cheap levels may not be "
                    "in the asymptotic range, and the prediction is uncertain",
                    p.order, *scene.study.order));
  for (std::size_t k = 0; k < kCheap; ++k)
    if (kSafety * std::abs(*cheap.values[k] - p.extrapolate) <= p.tolerance) {
      story.say(
          fmt::format("level {} ({}) already meets the target: {} = {:.8g}, {:.3g} from the extrapolate, {:.3g} "
                      "with the factor of safety, within {:.3g}; it took {}",
                      k + 1, level_text(results, k), target.name, *cheap.values[k],
                      std::abs(*cheap.values[k] - p.extrapolate), kSafety * std::abs(*cheap.values[k] - p.extrapolate),
                      p.tolerance, seconds_text(results.levels[k].usage.wall_seconds)));
      story.write(results, dir, heading);
      return 0;
    }

  // Whole windows: the scale rounded up to the next whole number of them, and at least
  // Celik et al.'s smallest ratio of 1.3 to the scene, below which the check after the run
  // cannot resolve an order from the finest three levels.
  const auto windows = static_cast<double>(scene.windows());
  varied = scales_for({1 / (r * r), 1 / r, 1, std::ceil(windows * std::max(p.scale, kSmallestRatio) - 1e-9) / windows});
  for (std::size_t i = 0; i < varied.size(); ++i) results.keys[i] = varied[i].key;
  results.levels.push_back(study::write_level(dir, document, varied, kCheap, {measure}, argument));
  const double scale = study::scales_of(scene, varied).back();
  Cost cost;
  try {
    cost = cost_of(results.levels.back(), request.build);
  } catch (const std::exception& e) {
    // The cheap levels' runs are worth their report even when level 4 cannot be started.
    story.say(fmt::format("level 4 ({}) cannot be estimated: {}", level_text(results, kCheap), e.what()));
    story.write(results, dir, heading);
    return 1;
  }
  story.say(
      fmt::format("level 4 ({}), {:.3g} times as fine as the scene, is the cheapest the model says reaches it: "
                  "modelled error {:.3g} with the safety factor, within {:.3g}",
                  level_text(results, kCheap), scale, modelled_error(p, 1, scale), p.tolerance));
  story.say(estimate::estimate_line(cost.estimate));
  const double available = available_bytes();
  std::string refused;
  if (available > 0 && cost.memory_bytes > available)
    refused = fmt::format("it would need about {:.0f} MB, and this host has {:.0f} MB available",
                          cost.memory_bytes / 1e6, available / 1e6);
  else if (request.budget && cost.estimate.wall_seconds > *request.budget)
    refused = fmt::format("it is estimated at {}, over --budget {}", seconds_text(cost.estimate.wall_seconds),
                          seconds_text(*request.budget));
  if (!refused.empty()) {
    story.say("level 4 refused: " + refused);
    results.levels.pop_back();
    for (study::Varied& v : varied) v.values.pop_back();
    story.write(results, dir, heading);
    return 1;
  }

  const bool ran = study::run_levels(results.levels, kCheap, results.keys, 1, kWho);
  const study::Quantity q = measured();
  const double wall = results.levels.back().usage.wall_seconds;
  if (!ran || !q.values.back()) {
    story.say("level 4 failed" + (q.problems.back().empty() ? std::string() : ": " + q.problems.back()));
    story.write(results, dir, heading);
    return 1;
  }
  story.say(fmt::format("level 4 took {}, estimated {} ({:.2f} of the estimate)", seconds_text(wall),
                        seconds_text(cost.estimate.wall_seconds), wall / cost.estimate.wall_seconds));
  const auto& last = q.estimates.back();
  const bool own = last && last->order && last->convergence == study::Convergence::Monotonic;
  const double extrapolate = own ? last->extrapolate : p.extrapolate;
  const double tolerance = target.tolerance.absolute(extrapolate);
  const double error = std::abs(*q.values.back() - extrapolate);
  story.say(fmt::format("{} = {:.8g} on level 4, {:.3g} from the extrapolate {:.8g} ({}): the target {} is {}",
                        target.name, *q.values.back(), error, extrapolate,
                        own ? "of levels 2 to 4" : "of the cheap levels: levels 2 to 4 do not converge monotonically",
                        target.tolerance.text, error <= tolerance ? "met" : "not met"));
  story.write(results, dir, heading);
  return error <= tolerance ? 0 : 1;
}

}  // namespace cosim::target
