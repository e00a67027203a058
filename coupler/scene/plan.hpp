// Which programs a scene needs. A scene declares effects, not programs: the plan starts the
// built-ins those effects need, every external participant, and fills in who provides and
// needs which data, so the coupler can route it.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "coupler/scene/scene.hpp"

namespace cosim::scene {

struct Plan {
  std::vector<Participant> start;    // in scene order, with provides and needs filled in
  std::vector<std::string> skipped;  // sections not started, with why: "fluid: no declared effect needs it"
};

// Throws SceneError when a declared effect needs a built-in that has no section, or when a
// started participant needs data nobody started provides (poses must come from exactly one).
// load_scene() already calls it, so on a loaded scene it only throws if the scene was edited.
Plan plan_participants(const Scene& scene);

bool is_builtin(std::string_view name);  // rigidbody, fluid, tracker

}  // namespace cosim::scene
