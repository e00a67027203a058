#include "coupler/scene/scene.hpp"

#include <algorithm>
#include <cmath>

#include "coupler/scene/names.hpp"

namespace cosim::scene {

bool Scene::has_effect(Effect e) const { return std::find(effects.begin(), effects.end(), e) != effects.end(); }

const Participant* Scene::participant(const std::string& name) const {
  auto it =
      std::find_if(participants.begin(), participants.end(), [&](const Participant& p) { return p.name == name; });
  return it == participants.end() ? nullptr : &*it;
}

std::size_t Scene::windows() const { return static_cast<std::size_t>(std::llround(time.end / coupling.window)); }

std::vector<std::string> Scene::body_names() const {
  std::vector<std::string> names;
  for (const Body& b : bodies) names.push_back(b.name);
  return names;
}

const char* to_string(Scheme s) { return scheme_names.at(static_cast<std::size_t>(s)); }
const char* to_string(Acceleration a) { return acceleration_names.at(static_cast<std::size_t>(a)); }
const char* to_string(Effect e) { return effect_names.at(static_cast<std::size_t>(e)); }
const char* to_string(Generator g) { return generator_names.at(static_cast<std::size_t>(g)); }

std::string describe(DataSet set) {
  std::string out;
  for (std::size_t i = 0; i < data_names.size(); ++i)
    if (set & (1u << i)) out += (out.empty() ? "" : ", ") + std::string(data_names[i]);
  return out.empty() ? "nothing" : out;
}

}  // namespace cosim::scene
