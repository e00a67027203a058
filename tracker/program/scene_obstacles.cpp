#include "tracker/program/scene_obstacles.hpp"

#include <set>

#include "tracker/program/csg_shape.hpp"
#include "tracker/program/scene_walls.hpp"

namespace cosim::tracker {

std::vector<Obstacle> read_obstacles(const scene::Reader& options, const std::filesystem::path& scene_file) {
  std::vector<Obstacle> out;
  if (!options.has("obstacles")) return out;
  std::set<std::string> names;
  for (const scene::Reader& r : options.maps("obstacles")) {
    std::string name = r.string("name");
    if (name.empty() || !names.insert(name).second) r.fail("name", "expected a unique, non-empty name");
    csg::Tree shape(read_shape(r.map("shape"), scene_file));
    const bool permeable = r.boolean("permeable", false);
    // A zone has no wall: `wall` on one stays unread, and finish() names it.
    BoundaryCondition wall;
    if (!permeable && r.has("wall")) wall = read_condition(r.map("wall"), false);
    r.finish();
    out.push_back({std::move(name), std::move(shape), permeable, wall});
  }
  return out;
}

}  // namespace cosim::tracker
