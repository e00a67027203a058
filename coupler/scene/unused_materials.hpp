// Material values the scene gives but no declared effect uses: friction coefficients count
// only with effects `contact` and `friction`, restitution only with `contact`. Such a scene
// is valid (switching an effect off should need no other edit), but it would run
// frictionless or inelastic without a word, so the programs that report to the user
// (`cosim check`, `cosim run`, `cosim-rigidbody --standalone`) print these as warnings.
#pragma once

#include <string>
#include <vector>

#include "coupler/scene/scene.hpp"

namespace cosim::scene {

// One message per ignored property (friction, restitution), naming the first body that
// sets it and counting the others, so a bed of a thousand grains gives one line:
// "scene.yaml:7: bodies[0].material.friction = 0.5: ignored for body 'box' and 2 more
// bodies: the scene's effects do not include 'friction'". Empty when nothing is ignored.
std::vector<std::string> unused_materials(const Scene& scene);

}  // namespace cosim::scene
