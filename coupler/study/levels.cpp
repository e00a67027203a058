#include "coupler/study/levels.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "coupler/study/argument_error.hpp"
#include "coupler/study/key_path.hpp"

namespace cosim::study {
namespace {

// The shortest text that reads back as the same double: 0.005 / 4 is written 0.00125.
YAML::Node number(double value) { return YAML::Node(fmt::format("{}", value)); }

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
  std::vector<double> counts;  // windows per level
  for (double s : scales) counts.push_back(std::max(1.0, std::round(windows * s)));
  // One division each, so that a value reads back as the shortest decimal: 1 / 400 = 0.0025.
  const auto each = [&](double total, double per_window) {
    std::vector<YAML::Node> values;
    for (double n : counts) values.push_back(number(total / (n * per_window)));
    return values;
  };
  const double end = scene.time.end;
  std::vector<Varied> out{{"coupling.window", each(end, 1), argument}};
  for (const scene::Participant& p : scene.participants)
    out.push_back({"participants." + p.name + ".dt", each(end, std::round(scene.coupling.window / p.dt)), argument});
  // IsDefined() before anything else: yaml-cpp throws on any other question to a missing key.
  const scene::Participant* fluid = scene.participant("fluid");
  const YAML::Node options = fluid != nullptr && fluid->options.IsMap() ? fluid->options : YAML::Node();
  const YAML::Node first = options.IsDefined() ? options["dt_initial"] : YAML::Node();
  if (first.IsDefined() && first.IsScalar())
    out.push_back(
        {"participants.fluid.options.dt_initial", each(end, scene.coupling.window / first.as<double>()), argument});
  // Field frames at the same times on every level, as far as whole windows allow, so that a
  // field measure reads the same instants and each level writes as many frames.
  const YAML::Node written = YAML::Load(scene.text)["output"];
  const YAML::Node frames = written.IsDefined() && written.IsMap() ? written["fields_every"] : YAML::Node();
  if (frames.IsDefined() && frames.IsScalar() && scene.output.fields_every > 0) {
    Varied every{"output.fields_every", {}, argument};
    for (double n : counts)
      every.values.push_back(YAML::Node(std::max(1L, std::lround(scene.output.fields_every * n / windows))));
    out.push_back(std::move(every));
  }
  const YAML::Node grid = options.IsDefined() ? options["grid"] : YAML::Node();
  const YAML::Node base = grid.IsDefined() && grid.IsMap() ? grid["cells"] : YAML::Node();
  if (base.IsDefined() && base.IsSequence()) {
    Varied cells{"participants.fluid.options.grid.cells", {}, argument};
    for (double n : counts) {
      YAML::Node level(YAML::NodeType::Sequence);
      level.SetStyle(YAML::EmitterStyle::Flow);
      // A single layer is a two-dimensional scene's: it stays one cell.
      for (const auto& c : base)
        level.push_back(c.as<double>() == 1 ? 1L : std::max(1L, std::lround(c.as<double>() * n / windows)));
      cells.values.push_back(level);
    }
    out.push_back(std::move(cells));
  }
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
