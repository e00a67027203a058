// fuzz_scene: the scene loader on any text. It either loads a scene or throws SceneError;
// anything else is a finding.
#include <string>

#include "coupler/scene/error.hpp"
#include "coupler/scene/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    cosim::scene::load_scene_from_string(std::string(reinterpret_cast<const char*>(data), size), "fuzz.yaml");
  } catch (const cosim::scene::SceneError&) {
  }
  return 0;
}
