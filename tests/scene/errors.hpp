#pragma once

#include <functional>
#include <string>

#include "coupler/scene/error.hpp"
#include "coupler/scene/scene.hpp"

// The message of the SceneError `f` throws, or "" if it throws none.
inline std::string thrown(const std::function<void()>& f) {
  try {
    f();
  } catch (const cosim::scene::SceneError& e) {
    return e.what();
  }
  return "";
}

// The message loading `yaml` as "scene.yaml" throws, or "" if the scene is valid.
inline std::string load_error(const std::string& yaml) {
  return thrown([&] { cosim::scene::load_scene_from_string(yaml, "scene.yaml"); });
}

// Lines 1-3 of most test scenes; what a test appends starts at line 4.
inline const std::string head = R"(time: {end: 1}
coupling: {window: 0.01}
domain: {min: [0, 0, 0], max: [1, 1, 1]}
)";
