// The top level of the scene file and the small sections; bodies and participants have
// their own files.
#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "coupler/scene/error.hpp"
#include "coupler/scene/names.hpp"
#include "coupler/scene/plan.hpp"
#include "coupler/scene/sections.hpp"

namespace cosim::scene {
namespace {

namespace fs = std::filesystem;

YAML::Node parse(const std::string& text, const std::string& file) {
  try {
    return YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw SceneError(file, e.mark.line + 1, "", "", "invalid YAML: " + e.msg);
  }
}

Time read_time(const Reader& r) {
  const Time t{r.number("end", Range::above(0))};
  r.finish();
  return t;
}

// An interface name or an address of this host; every address at once would hand the
// participants an endpoint (0.0.0.0) they cannot connect to.
std::string read_interface(const Reader& r, Transport transport) {
  const std::string value = r.string("interface");
  if (transport != Transport::Tcp)
    r.fail("interface", "needs coupling.transport: tcp (an ipc socket is reached from this host only)");
  if (value.empty() || value.find_first_of(" \t/[]*") != std::string::npos || value.find("://") != std::string::npos)
    r.fail("interface", "expected a network interface (ib0, eth0) or an address of this host (10.1.2.3)");
  if (value == "0.0.0.0" || value == "::")
    r.fail("interface", "listening on every address gives participants no address to connect to; name one");
  return value;
}

Coupling read_coupling(const Reader& r, const Time& time) {
  Coupling c;
  c.window = r.number("window", Range::above(0));
  if (c.window > time.end) r.fail("window", fmt::format("must be <= time.end (time.end = {})", time.end));
  if (!whole_multiple(time.end, c.window))
    r.fail("window", fmt::format("time.end is not a whole number of windows (time.end = {})", time.end));
  c.scheme = pick(r, "scheme", scheme_names, c.scheme);
  c.acceleration = pick(r, "acceleration", acceleration_names, c.acceleration);
  c.relaxation = r.number("relaxation", c.relaxation, Range::left_open(0, 1));
  c.max_iterations = r.integer("max_iterations", c.max_iterations, Range::at_least(1));
  c.tolerance = r.number("tolerance", c.tolerance, Range::open(0, 1));
  c.force_tolerance = r.number("force_tolerance", c.force_tolerance, Range::at_least(0));
  c.transport = pick(r, "transport", transport_names, c.transport);
  if (r.has("interface")) c.interface = read_interface(r, c.transport);
  c.timeout = r.number("timeout", c.timeout, Range::above(0));
  c.heartbeat = r.number("heartbeat", c.heartbeat, Range::at_least(0.1));
  r.finish();
  return c;
}

Output read_output(const Reader& r) {
  Output o;
  o.file = r.string("file", o.file);
  if (o.file.empty()) r.fail("file", "must not be empty");
  o.every = r.integer("every", o.every, Range::at_least(1));
  o.checkpoint_every = r.integer("checkpoint_every", o.checkpoint_every, Range::at_least(1));
  o.fields_every = r.integer("fields_every", o.fields_every, Range::at_least(0));
  r.finish();
  return o;
}

std::vector<Effect> read_effects(const Reader& r) {
  std::vector<Effect> effects;
  for (std::size_t i : r.choices("effects", effect_names)) effects.push_back(static_cast<Effect>(i));
  return effects;
}

Study read_study(const Reader& r) {
  Study s;
  if (r.has("measure")) {
    const Reader m = r.map("measure");
    for (const std::string& name : m.keys()) {
      // Names end up in file names (the study's plots).
      if (!is_name(name)) m.fail(name, name_rule);
      s.measures.push_back({name, m.string(name), m.line(name)});
    }
    m.finish();
  }
  if (r.has("order")) s.order = r.number("order", Range::above(0));
  r.finish();
  return s;
}

}  // namespace

Domain read_box(const Reader& r) {
  const Domain d{r.vec3("min"), r.vec3("max")};
  for (int k = 0; k < 3; ++k) {
    if (d.max[k] <= d.min[k]) r.fail("max", fmt::format("must be greater than {} in every component", r.path("min")));
    // Every width, volume and cell count of the box is computed from max - min.
    if (!std::isfinite(d.max[k] - d.min[k]))
      r.fail("max", fmt::format("is too far from {}: the box's width is beyond double precision", r.path("min")));
  }
  r.finish();
  return d;
}

Scene load_scene(const fs::path& file) {
  if (!fs::is_regular_file(file))
    throw SceneError(file.string(), 0, "", "",
                     fs::exists(file) ? "not a file (a scene is a YAML file)" : "no such scene file");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw SceneError(file.string(), 0, "", "", "cannot open the scene file");
  std::ostringstream text;
  text << in.rdbuf();
  return load_scene_from_string(text.str(), file);
}

Scene load_scene_from_string(const std::string& text, const fs::path& file) {
  Scene s;
  s.file = file;
  s.text = text;
  const Reader r(parse(text, file.string()), file.string(), "");
  s.time = read_time(r.map("time"));
  s.coupling = read_coupling(r.map("coupling"), s.time);
  if (r.has("output")) s.output = read_output(r.map("output"));
  s.gravity = r.vec3("gravity", s.gravity);
  s.domain = read_box(r.map("domain"));
  s.folder = file.parent_path();
  if (r.has("folder")) {
    s.folder = s.folder / r.string("folder");
    if (!fs::is_directory(s.folder)) r.fail("folder", "no such folder: " + s.folder.string());
  }
  if (r.has("bodies")) {
    Bodies b = read_bodies(r.maps("bodies"), s.domain, s.folder, s.output.file);
    s.bodies = std::move(b.bodies);
    s.generators = std::move(b.generators);
  }
  if (r.has("effects")) {
    s.effects = read_effects(r);
    s.effects_line = r.line("effects");
  }
  if (r.has("participants")) s.participants = read_participants(r.map("participants"), s.coupling, s.folder);
  if (r.has("study")) s.study = read_study(r.map("study"));
  r.finish();
  // A scene whose effects no set of participants can serve is as wrong as a negative
  // radius, and must be caught before anything starts.
  plan_participants(s);
  return s;
}

}  // namespace cosim::scene
