#include "coupler/study/measures.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "coupler/scene/error.hpp"
#include "coupler/scene/sections.hpp"
#include "coupler/study/argument_error.hpp"

namespace cosim::study {

std::string mismatch(const Measure& m, const scene::Scene& scene) {
  const std::vector<std::string> names = scene.body_names();
  for (const std::string& body : bodies_of(m.expression)) {
    if (std::find(names.begin(), names.end(), body) != names.end()) continue;
    // A generated packing can name thousands: the first few say enough.
    const std::size_t shown = std::min<std::size_t>(names.size(), 8);
    return fmt::format("no body '{}' in the scene (its bodies: {}{})", body,
                       fmt::join(names.begin(), names.begin() + static_cast<std::ptrdiff_t>(shown), ", "),
                       names.size() > shown ? ", ..."
                       : names.empty()      ? "none"
                                            : "");
  }
  for (const std::string& p : participants_of(m.expression)) {
    if (scene.participant(p) == nullptr) {
      std::vector<std::string> names;
      for (const scene::Participant& q : scene.participants) names.push_back(q.name);
      return fmt::format("no participant '{}' in the scene (its participants: {})", p,
                         names.empty() ? "none" : fmt::format("{}", fmt::join(names, ", ")));
    }
    if (scene.output.fields_every == 0) return "output.fields_every is 0: the run writes no fields to measure";
  }
  if (const output::Region* r = region_of(m.expression)) {
    const auto& d = scene.domain;
    for (int a = 0; a < 3; ++a)
      if (r->hi[a] < d.min[a] || r->lo[a] > d.max[a])
        return fmt::format("the field's region [{}, {}] on axis {} lies outside the domain [{}, {}]", r->lo[a],
                           r->hi[a], "xyz"[a], d.min[a], d.max[a]);
  }
  if (latest_time(m.expression) > scene.time.end)
    return fmt::format("mean() reaches t = {} s, past time.end = {} s", latest_time(m.expression), scene.time.end);
  return "";
}

std::vector<Measure> measures_of(const scene::Scene& scene, const std::vector<std::string>& arguments) {
  std::vector<Measure> out;
  for (const scene::StudyMeasure& given : scene.study.measures) {
    const auto fail = [&](const std::string& problem) {
      throw scene::SceneError(scene.file.string(), given.line, "study.measure." + given.name, given.expression,
                              problem);
    };
    try {
      out.push_back(parse_measure(given.name, given.expression));
    } catch (const ArgumentError& e) {
      fail(e.what());
    }
    if (const std::string why = mismatch(out.back(), scene); !why.empty()) fail(why);
  }
  for (const std::string& argument : arguments) {
    const std::string where = "--measure " + argument;
    const std::size_t eq = argument.find('=');
    if (eq == std::string::npos)
      throw ArgumentError(where + ": expected NAME=EXPRESSION, such as peak=max(body:ball:velocity.z)");
    const std::string name = argument.substr(0, eq);
    if (!scene::is_name(name)) throw ArgumentError(fmt::format("{}: the name: {}", where, scene::name_rule));
    Measure m;
    try {
      m = parse_measure(name, argument.substr(eq + 1));
    } catch (const ArgumentError& e) {
      throw ArgumentError(where + ": " + e.what());
    }
    if (const std::string why = mismatch(m, scene); !why.empty()) throw ArgumentError(where + ": " + why);
    const auto same = std::find_if(out.begin(), out.end(), [&](const Measure& o) { return o.name == name; });
    if (same == out.end())
      out.push_back(std::move(m));
    else if (same - out.begin() < static_cast<std::ptrdiff_t>(scene.study.measures.size()))
      *same = std::move(m);
    else
      throw ArgumentError(fmt::format("{}: another --measure has the name '{}'", where, name));
  }
  return out;
}

}  // namespace cosim::study
