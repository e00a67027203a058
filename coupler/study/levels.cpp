#include "coupler/study/levels.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "coupler/study/argument_error.hpp"
#include "coupler/study/key_path.hpp"

namespace cosim::study {
namespace {

// Relative tolerances below this are round-off's (a few thousand times the double's
// epsilon, accumulated over a solve's sums): --refine shrinks none beyond it.
constexpr double kTightestTolerance = 1e-12;

// The shortest text that reads back as the same double: 0.005 / 4 is written 0.00125.
YAML::Node number(double value) { return YAML::Node(fmt::format("{}", value)); }

// node[key] where node is a map that has it, else a null node (neither scalar, list nor
// map). IsDefined() comes before anything else: yaml-cpp throws on any other question to a
// missing key.
YAML::Node at(const YAML::Node& node, const char* key) {
  return node.IsDefined() && node.IsMap() && node[key].IsDefined() ? node[key] : YAML::Node();
}

// Cells per axis at `ratio` times the resolution; a single layer is a two-dimensional
// scene's (or a channel's periodic depth) and stays one cell.
YAML::Node cells_at(const YAML::Node& base, double ratio) {
  YAML::Node level(YAML::NodeType::Sequence);
  level.SetStyle(YAML::EmitterStyle::Flow);
  for (const auto& c : base)
    level.push_back(c.as<double>() == 1 ? 1L : std::max(1L, std::lround(c.as<double>() * ratio)));
  return level;
}

// How many times the cells of cells_at(base, ratio) outnumber base's.
double cell_count_ratio(const YAML::Node& base, double ratio) {
  double count = 1;
  for (std::size_t k = 0; k < base.size(); ++k) count *= cells_at(base, ratio)[k].as<double>() / base[k].as<double>();
  return count;
}

}  // namespace

Varied parse_vary(const std::string& argument) {
  const std::string where = "--vary " + argument;
  const std::size_t eq = argument.find('=');
  if (eq == std::string::npos || eq == 0)
    throw ArgumentError(where + ": expected KEY=V1,V2,... (coupling.window=0.01,0.005,0.0025)");
  Varied v{argument.substr(0, eq), {}, where};
  YAML::Node values;
  try {
    // The values as one flow list, so that a list value keeps its commas: [20,20,40],[40,40,80].
    values = YAML::Load("[" + argument.substr(eq + 1) + "]");
  } catch (const YAML::Exception& e) {
    throw ArgumentError(fmt::format("{}: the values are not YAML: {}", where, e.msg));
  }
  for (const auto& value : values) {
    if (value.IsNull()) throw ArgumentError(where + ": a value is empty");
    v.values.push_back(value);
  }
  if (v.values.size() < 2) throw ArgumentError(where + ": give at least two values, coarsest first");
  return v;
}

Setting parse_set(const std::string& argument) {
  const std::string where = "--set " + argument;
  const std::size_t eq = argument.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == argument.size())
    throw ArgumentError(where + ": expected KEY=VALUE (time.end=1.0)");
  try {
    return {argument.substr(0, eq), YAML::Load(argument.substr(eq + 1)), where};
  } catch (const YAML::Exception& e) {
    throw ArgumentError(fmt::format("{}: the value is not YAML: {}", where, e.msg));
  }
}

std::vector<Varied> scaled(const scene::Scene& scene, const std::vector<double>& scales, const std::string& argument) {
  const auto windows = static_cast<double>(scene.windows());
  std::vector<double> counts, ratios;  // windows per level, and their ratio to the scene's
  for (double s : scales) {
    counts.push_back(std::max(1.0, std::round(windows * s)));
    ratios.push_back(counts.back() / windows);
  }
  // One division each, so that a value reads back as the shortest decimal: 1 / 400 = 0.0025.
  const auto each = [&](double total, double per_window) {
    std::vector<YAML::Node> values;
    for (double n : counts) values.push_back(number(total / (n * per_window)));
    return values;
  };
  const auto of_ratio = [&](const auto& value) {
    std::vector<YAML::Node> values;
    for (double r : ratios) values.push_back(value(r));
    return values;
  };
  const double end = scene.time.end;
  std::vector<Varied> out{{"coupling.window", each(end, 1), argument}};
  for (const scene::Participant& p : scene.participants)
    out.push_back({"participants." + p.name + ".dt", each(end, std::round(scene.coupling.window / p.dt)), argument});
  // What the scene writes, so that a default is left to its program.
  const YAML::Node document = YAML::Load(scene.text);
  const YAML::Node fluid = at(at(at(document, "participants"), "fluid"), "options");
  if (const YAML::Node first = at(fluid, "dt_initial"); first.IsScalar())
    out.push_back(
        {"participants.fluid.options.dt_initial", each(end, scene.coupling.window / first.as<double>()), argument});
  // Field frames at the same times on every level, as far as whole windows allow, so that a
  // field measure reads the same instants and each level writes as many frames.
  const auto frames_every = [&](double r) { return std::max(1L, std::lround(scene.output.fields_every * r)); };
  const bool frames = at(at(document, "output"), "fields_every").IsScalar() && scene.output.fields_every > 0;
  if (frames)
    out.push_back({"output.fields_every", of_ratio([&](double r) { return YAML::Node(frames_every(r)); }), argument});
  if (const YAML::Node grid = at(at(fluid, "grid"), "cells"); grid.IsSequence())
    out.push_back(
        {"participants.fluid.options.grid.cells", of_ratio([&](double r) { return cells_at(grid, r); }), argument});
  // The tracker's mesh refines as the grid does, and its particles per cell stay as written
  // (`per_cell` as it is, `total` times the cells' growth g) with each simulator standing for
  // 1/g as many molecules (`weight`), so that the gas is the same and its statistical error
  // falls with the cells.
  const YAML::Node tracker = at(at(at(document, "participants"), "tracker"), "options");
  // Particles are written with the fields: every the same number of field frames.
  if (const YAML::Node every = at(at(tracker, "particle_output"), "every"); frames && every.IsScalar())
    out.push_back({"participants.tracker.options.particle_output.every", of_ratio([&](double r) {
                     return YAML::Node(every.as<long>() / scene.output.fields_every * frames_every(r));
                   }),
                   argument});
  const YAML::Node mesh = at(tracker, "mesh");
  std::vector<double> grown;  // the tracker's cells over the scene's, per level
  if (const YAML::Node box = at(mesh, "cells"); box.IsSequence()) {
    out.push_back(
        {"participants.tracker.options.mesh.cells", of_ratio([&](double r) { return cells_at(box, r); }), argument});
    for (double r : ratios) grown.push_back(cell_count_ratio(box, r));
  } else if (const YAML::Node points = at(mesh, "points"); points.IsScalar()) {
    const auto seeds = [&](double r) { return std::max(1L, std::lround(points.as<double>() * r * r * r)); };
    out.push_back({"participants.tracker.options.mesh.points", of_ratio([&](double r) { return YAML::Node(seeds(r)); }),
                   argument});
    for (double r : ratios) grown.push_back(static_cast<double>(seeds(r)) / points.as<double>());
  }
  const YAML::Node particles = at(tracker, "particles");
  if (const YAML::Node total = at(particles, "total"); !grown.empty() && total.IsScalar()) {
    Varied v{"participants.tracker.options.particles.total", {}, argument};
    for (double g : grown) v.values.push_back(YAML::Node(std::lround(total.as<double>() * g)));
    out.push_back(std::move(v));
  }
  if (!grown.empty() && particles.IsMap()) {
    const YAML::Node weight = at(particles, "weight");
    Varied v{"participants.tracker.options.particles.weight", {}, argument};
    for (double g : grown) v.values.push_back(number((weight.IsScalar() ? weight.as<double>() : 1.0) / g));
    out.push_back(std::move(v));
  }
  // A tolerance the scene sets shrinks on finer levels as a second-order discretization error
  // does (s^-2), so that what the iterations leave stays the same small part of each level's
  // error, down to kTightestTolerance; a coarser level (--target's) keeps it, never looser
  // than the scene asks. The coupling's counts only where the scheme iterates.
  const std::pair<const char*, YAML::Node> tolerances[] = {
      {"coupling.tolerance",
       scene::is_implicit(scene.coupling.scheme) ? at(at(document, "coupling"), "tolerance") : YAML::Node()},
      {"participants.rigidbody.options.tolerance",
       at(at(at(at(document, "participants"), "rigidbody"), "options"), "tolerance")},
      {"participants.fluid.options.bodies.tolerance", at(at(fluid, "bodies"), "tolerance")}};
  for (const auto& [key, tolerance] : tolerances)
    if (tolerance.IsScalar())
      out.push_back({key, of_ratio([&](double r) {
                       const double written = tolerance.as<double>();
                       return number(
                           std::max(std::min(written, kTightestTolerance), written / std::pow(std::max(r, 1.0), 2)));
                     }),
                     argument});
  return out;
}

std::vector<Varied> refine(const scene::Scene& scene, double factor, int levels) {
  std::vector<double> scales;
  for (int k = 0; k < levels; ++k) scales.push_back(std::pow(factor, k));
  return scaled(scene, scales, fmt::format("--refine {}", factor));
}

std::vector<double> scales_of(const scene::Scene& scene, const std::vector<Varied>& varied) {
  std::vector<double> out;
  for (const YAML::Node& window : varied.front().values) out.push_back(scene.coupling.window / window.as<double>());
  return out;
}

std::size_t level_count(const std::vector<Varied>& varied) {
  for (const Varied& v : varied)
    if (v.values.size() != varied.front().values.size())
      throw ArgumentError(fmt::format("{} gives {} values but {} gives {}: every --vary needs one value per level",
                                      v.argument, v.values.size(), varied.front().argument,
                                      varied.front().values.size()));
  return varied.front().values.size();
}

YAML::Node variant(const YAML::Node& scene, const std::vector<Varied>& varied, std::size_t level) {
  YAML::Node copy = YAML::Clone(scene);
  for (const Varied& v : varied) set_at(copy, v.key, v.values[level], v.argument);
  return copy;
}

std::string text(const YAML::Node& value) {
  YAML::Emitter out;
  out << YAML::Flow << value;
  return out.c_str();
}

}  // namespace cosim::study
