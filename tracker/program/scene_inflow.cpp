#include "tracker/program/scene_inflow.hpp"

#include <algorithm>

namespace cosim::tracker::program {

std::vector<tracking::Inflow> read_inflows(const scene::Reader& options, const mesh::Mesh& mesh,
                                           const tracking::Boundaries& boundaries, double mass, double weight) {
  std::vector<tracking::Inflow> inflows;
  if (!options.has("inflow")) return inflows;
  std::vector<const char*> names;
  for (const std::string& p : mesh.patches) names.push_back(p.c_str());
  for (const scene::Reader& r : options.maps("inflow")) {
    std::vector<Index> patches;
    for (const std::size_t p : r.choices("patches", names)) {
      if (boundaries.patches[p].kind != tracking::BoundaryKind::open)
        r.fail("patches", "patch " + mesh.patches[p] +
                              " is not open: a stream enters where the gas can leave too (boundaries: {" +
                              mesh.patches[p] + ": {kind: open}})");
      patches.push_back(static_cast<Index>(p));
    }
    tracking::Stream stream;
    stream.number_density = r.number("number_density", scene::Range::above(0));
    const scene::Vec3 v = r.vec3("velocity", scene::Vec3{0, 0, 0});
    stream.velocity = {v[0], v[1], v[2]};
    stream.temperature = r.number("temperature", scene::Range::above(0));
    stream.mass = mass;
    stream.weight = weight;
    r.finish();
    inflows.emplace_back(mesh, patches, stream);
  }
  return inflows;
}

}  // namespace cosim::tracker::program
