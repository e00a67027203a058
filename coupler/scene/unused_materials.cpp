#include "coupler/scene/unused_materials.hpp"

#include <fmt/format.h>

#include <initializer_list>

namespace cosim::scene {
namespace {

// "do not include 'friction'", or "include neither 'contact' nor 'friction'".
std::string missing_effects(const Scene& s, std::initializer_list<Effect> needed) {
  std::vector<std::string> missing;
  for (Effect e : needed)
    if (!s.has_effect(e)) missing.push_back(fmt::format("'{}'", to_string(e)));
  if (missing.empty()) return "";
  if (missing.size() == 1) return "do not include " + missing[0];
  return "include neither " + missing[0] + " nor " + missing[1];
}

void warn_unused(const Scene& s, const char* key, double Material::*value, std::initializer_list<Effect> needed,
                 std::vector<std::string>& out) {
  const std::string missing = missing_effects(s, needed);
  if (missing.empty()) return;
  std::vector<std::size_t> setting;  // bodies that give the property
  for (std::size_t i = 0; i < s.bodies.size(); ++i)
    if (s.bodies[i].material.*value != 0.0) setting.push_back(i);
  if (setting.empty()) return;
  const Body& first = s.bodies[setting[0]];
  const std::size_t more = setting.size() - 1;
  const std::string others = more == 0 ? "" : fmt::format(" and {} more bod{}", more, more == 1 ? "y" : "ies");
  out.push_back(fmt::format("{}:{}: bodies[{}].material.{} = {}: ignored for body '{}'{}: the scene's effects {}",
                            s.file.string(), first.material_line, setting[0], key, first.material.*value, first.name,
                            others, missing));
}

}  // namespace

std::vector<std::string> unused_materials(const Scene& scene) {
  using enum Effect;
  std::vector<std::string> out;
  warn_unused(scene, "friction", &Material::friction, {Contact, Friction}, out);
  warn_unused(scene, "restitution", &Material::restitution, {Contact}, out);
  return out;
}

}  // namespace cosim::scene
