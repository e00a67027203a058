#include "coupler/scene/plan.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <optional>

#include "coupler/scene/error.hpp"
#include "coupler/scene/names.hpp"

namespace cosim::scene {
namespace {

using enum Effect;

constexpr DataSet bit(Data d) { return static_cast<DataSet>(d); }

// The first declared effect among `wanted`: the one to name if its program is missing.
std::optional<Effect> first_of(const Scene& s, std::initializer_list<Effect> wanted) {
  for (Effect e : s.effects)
    if (std::find(wanted.begin(), wanted.end(), e) != wanted.end()) return e;
  return std::nullopt;
}

bool any_free_body(const Scene& s) {
  return std::any_of(s.bodies.begin(), s.bodies.end(), [](const Body& b) { return !b.fixed; });
}

// Tracers ride the fluid's velocity unless the gas is rarefied, where the tracker has its own.
bool tracers_need_fluid(const Scene& s) { return s.has_effect(Tracers) && !s.has_effect(RarefiedGas); }

struct Builtin {
  const char* name;
  std::optional<Effect> needed_by;  // none: not started
  const char* idle;                 // why not, for the launcher's report
};

std::array<Builtin, 3> builtins(const Scene& s) {
  const std::optional<Effect> moves = first_of(s, {Gravity, Buoyancy, Contact, Friction, Hydrodynamics, RarefiedGas});
  const char* unneeded = "no declared effect needs it";
  return {{
      {"rigidbody", any_free_body(s) ? moves : std::nullopt, moves ? "no body is free to move" : unneeded},
      {"fluid", tracers_need_fluid(s) ? first_of(s, {Hydrodynamics, Tracers}) : first_of(s, {Hydrodynamics}), unneeded},
      {"tracker", first_of(s, {RarefiedGas, Tracers}), unneeded},
  }};
}

[[noreturn]] void fail(const Scene& s, const Participant& p, const std::string& problem) {
  throw SceneError(s.file.string(), p.line, "participants." + p.name, "", problem);
}

void assign_roles(const Scene& s, std::vector<Participant>& start) {
  // Fixed bodies' poses are part of INIT; only moving ones must be sent every window.
  const DataSet poses = any_free_body(s) ? bit(Data::Poses) : 0;
  const DataSet fields = tracers_need_fluid(s) ? bit(Data::Fields) : 0;
  // The run file takes the fluid's and the tracker's fields too.
  const DataSet written = s.output.fields_every > 0 ? bit(Data::Fields) : 0;
  for (Participant& p : start) {
    if (p.name == "fluid") {
      p.provides = (s.has_effect(Hydrodynamics) ? bit(Data::Forces) : 0) | fields | written;
      p.needs = poses;
    } else if (p.name == "tracker") {
      p.provides = (s.has_effect(RarefiedGas) ? bit(Data::Forces) : 0) | written;
      p.needs = poses | fields;
    }
  }
  // Gravity alone is the rigid bodies' own business: they wait for forces only if someone sends them.
  const bool forces =
      std::any_of(start.begin(), start.end(), [](const Participant& p) { return has(p.provides, Data::Forces); });
  for (Participant& p : start)
    if (p.name == "rigidbody") {
      p.provides = bit(Data::Poses);
      p.needs = forces ? bit(Data::Forces) : 0;
    }
}

void check_supply(const Scene& s, const std::vector<Participant>& start) {
  // The coupler moves bodies with one participant's poses and the others' forces; one
  // program in both roles would have to answer twice per window.
  for (const Participant& p : start)
    if (has(p.provides, Data::Poses) && has(p.provides, Data::Forces))
      fail(s, p, "provides both poses and forces; a participant takes one of the two roles");
  for (std::size_t i = 0; i < data_names.size(); ++i) {
    const Data d = static_cast<Data>(1u << i);
    std::vector<const Participant*> providers, consumers;
    for (const Participant& p : start) {
      if (has(p.provides, d)) providers.push_back(&p);
      if (has(p.needs, d)) consumers.push_back(&p);
    }
    if (consumers.empty()) continue;
    if (providers.empty())
      fail(s, *consumers.front(), fmt::format("needs {} but no started participant provides them", data_names[i]));
    // Two sources of body motion would fight over every body.
    if (d == Data::Poses && providers.size() > 1)
      fail(s, *providers[1],
           fmt::format("provides poses, as does '{}'; only one participant may provide them", providers[0]->name));
  }
}

}  // namespace

bool is_builtin(std::string_view name) { return name == "rigidbody" || name == "fluid" || name == "tracker"; }

Plan plan_participants(const Scene& s) {
  const std::array<Builtin, 3> table = builtins(s);
  for (const Builtin& b : table)
    if (b.needed_by && !s.participant(b.name))
      throw SceneError(s.file.string(), s.effects_line, "effects", "",
                       fmt::format("effect '{}' needs participant '{}': add participants.{}", to_string(*b.needed_by),
                                   b.name, b.name));
  Plan plan;
  for (const Participant& p : s.participants) {
    auto b = std::find_if(table.begin(), table.end(), [&](const Builtin& b) { return p.name == b.name; });
    if (b == table.end() || b->needed_by)
      plan.start.push_back(p);
    else
      plan.skipped.push_back(p.name + ": " + b->idle);
  }
  assign_roles(s, plan.start);
  check_supply(s, plan.start);
  return plan;
}

}  // namespace cosim::scene
