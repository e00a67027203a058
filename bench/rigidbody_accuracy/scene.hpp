// The two benchmark scenes. A builder fills an empty World and says in which length its
// errors are measured and how long it runs.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "rigidbody/world/world.hpp"

namespace cosim::bench {

struct Scene;
using SceneBuilder = std::function<Scene(rigidbody::world::World&)>;

struct Scene {
  std::string name;
  double size = 0.0;      // sphere radius or box half size: the unit of every length error
  double duration = 0.0;  // simulated seconds
  bool at_rest = false;   // the exact answer is the start state (nothing should move)
  bool hard = false;      // a hard case of the stability suite, which only the default solver must hold
};

// 91 spheres (square layers 6x6 ... 1) with friction 0.5 on a fixed 7x7 layer of spheres
// on a fixed floor, a 1e-3 r gap between all of them, settling under gravity for 1 s.
Scene build_pyramid(rigidbody::world::World& world);

// Ten 0.2 m boxes with friction 0.5 exactly touching on a fixed floor, for 2 s.
Scene build_box_stack(rigidbody::world::World& world);

// The hard resting cases of the stability suite (tests/rigidbody/world/hard_stack.hpp),
// 10 s each, lengths in units of the smallest body's size.
std::vector<SceneBuilder> hard_scenes();

}  // namespace cosim::bench
