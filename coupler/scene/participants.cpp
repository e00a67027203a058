#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "coupler/scene/names.hpp"
#include "coupler/scene/plan.hpp"
#include "coupler/scene/sections.hpp"

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

bool is_host_name(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(),
                                   [](unsigned char c) { return std::isalnum(c) || c == '.' || c == '-' || c == '_'; });
}

// At most one of hosts, hostfile and het_group. Ranks elsewhere reach the coupler only on a
// network interface it listens on, with the keys tcp brings.
Placement read_placement(const Reader& r, const Coupling& coupling, const std::filesystem::path& dir) {
  Placement p;
  std::vector<std::string> given;
  for (const char* key : {"hosts", "hostfile", "het_group"})
    if (r.has(key)) given.emplace_back(key);
  if (given.empty()) return p;
  if (given.size() > 1) r.fail(given[1], "give one of hosts, hostfile and het_group, not " + given[0] + " too");
  const std::string& key = given.front();
  if (key == "hosts" && r.node("hosts").IsScalar()) {
    if (r.string("hosts") != "scheduler") r.fail("hosts", "expected a list of host names, or scheduler");
    p.scheduler = true;
  } else if (key == "hosts") {
    p.hosts = r.strings("hosts");
    if (p.hosts.empty()) r.fail("hosts", "expected at least one host name");
    for (const auto& host : p.hosts)
      if (!is_host_name(host)) r.fail("hosts", "'" + host + "' is not a host name");
  } else if (key == "hostfile") {
    p.hostfile = dir / r.string("hostfile");
    if (!std::filesystem::is_regular_file(p.hostfile)) r.fail("hostfile", "no such file (" + p.hostfile.string() + ")");
  } else {
    p.het_group = r.integer("het_group", Range::at_least(0));
  }
  if (coupling.transport != Transport::Tcp || coupling.interface.empty())
    r.fail(key,
           "ranks on other hosts reach the coupler only over a network: set coupling.transport: tcp and "
           "coupling.interface");
  return p;
}

Participant read_participant(const Reader& r, const std::string& name, int line, const Coupling& coupling,
                             const std::filesystem::path& dir) {
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
  p.placement = read_placement(r, coupling, dir);
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

std::vector<Participant> read_participants(const Reader& r, const Coupling& coupling,
                                           const std::filesystem::path& dir) {
  std::vector<Participant> participants;
  for (const std::string& name : r.keys()) {
    if (!is_name(name)) r.fail(name, name_rule);
    participants.push_back(read_participant(r.map(name), name, r.line(name), coupling, dir));
  }
  r.finish();
  return participants;
}

}  // namespace cosim::scene
