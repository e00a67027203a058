#include <fmt/format.h>

#include "scene/names.hpp"
#include "scene/plan.hpp"
#include "scene/sections.hpp"

namespace cosim::scene {
namespace {

DataSet read_data(const Reader& r, const std::string& key) {
  DataSet set = 0;
  for (std::size_t i : r.choices(key, data_names)) set |= 1u << i;
  return set;
}

std::vector<std::string> read_command(const Reader& r) {
  std::vector<std::string> command = r.strings("command");
  if (command.empty()) r.fail("command", "must name a program");
  return command;
}

Participant read_participant(const Reader& r, const std::string& name, int line, const Coupling& coupling) {
  Participant p;
  p.name = name;
  p.line = line;
  if (is_builtin(name)) {
    // The plan derives a built-in's roles from the effects; a second source of truth
    // could only disagree with it.
    for (const std::string& key : r.keys())
      if (key == "provides" || key == "needs")
        r.fail(key, fmt::format("'{}' is a built-in participant whose roles follow from the effects; remove this key",
                                name));
    if (r.has("command")) p.command = read_command(r);
  } else {
    p.command = read_command(r);
    p.provides = read_data(r, "provides");
    if (r.has("needs")) p.needs = read_data(r, "needs");
  }
  p.ranks = r.integer("ranks", p.ranks, Range::at_least(1));
  p.dt = r.number("dt", Range::above(0));
  const std::string window = fmt::format("(coupling.window = {})", coupling.window);
  if (p.dt > coupling.window) r.fail("dt", "window shorter than the participant's dt " + window);
  if (!whole_multiple(coupling.window, p.dt)) r.fail("dt", "coupling.window is not a whole number of steps " + window);
  p.options = YAML::Node(YAML::NodeType::Map);
  if (r.has("options")) {
    r.map("options");  // the program validates the keys; here they only have to form a mapping
    p.options = r.node("options");
  }
  r.finish();
  return p;
}

}  // namespace

std::vector<Participant> read_participants(const Reader& r, const Coupling& coupling) {
  std::vector<Participant> participants;
  for (const std::string& name : r.keys()) {
    if (!is_name(name)) r.fail(name, name_rule);
    participants.push_back(read_participant(r.map(name), name, r.line(name), coupling));
  }
  r.finish();
  return participants;
}

}  // namespace cosim::scene
