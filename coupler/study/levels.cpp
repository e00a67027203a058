#include "coupler/study/levels.hpp"

#include <fmt/format.h>

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

std::vector<Varied> refine(const scene::Scene& scene, double factor, int levels) {
  const std::string where = fmt::format("--refine {}", factor);
  std::vector<Varied> out{{"coupling.window", {}, where}};
  for (int k = 0; k < levels; ++k) out[0].values.push_back(number(scene.coupling.window / std::pow(factor, k)));
  for (const scene::Participant& p : scene.participants) {
    Varied dt{"participants." + p.name + ".dt", {}, where};
    for (int k = 0; k < levels; ++k) dt.values.push_back(number(p.dt / std::pow(factor, k)));
    out.push_back(std::move(dt));
  }
  // IsDefined() before anything else: yaml-cpp throws on any other question to a missing key.
  const scene::Participant* fluid = scene.participant("fluid");
  const YAML::Node grid = fluid != nullptr && fluid->options.IsMap() ? fluid->options["grid"] : YAML::Node();
  const YAML::Node base = grid.IsDefined() && grid.IsMap() ? grid["cells"] : YAML::Node();
  if (base.IsDefined() && base.IsSequence()) {
    Varied cells{"participants.fluid.options.grid.cells", {}, where};
    for (int k = 0; k < levels; ++k) {
      YAML::Node level(YAML::NodeType::Sequence);
      level.SetStyle(YAML::EmitterStyle::Flow);
      for (const auto& n : base)
        level.push_back(std::lround(n.as<double>() * std::pow(factor, k)));
      cells.values.push_back(level);
    }
    out.push_back(std::move(cells));
  }
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
