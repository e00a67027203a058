#include "tracker/program/scene_balance.hpp"

namespace cosim::tracker::program {

step::Balance read_balance(const scene::Reader& options) {
  step::Balance b;
  if (!options.has("balance")) return b;
  const scene::Reader r = options.map("balance");
  b.every = r.integer("every", b.every, scene::Range::at_least(0));
  b.threshold = r.number("threshold", b.threshold, scene::Range::at_least(1));
  r.finish();
  return b;
}

}  // namespace cosim::tracker::program
