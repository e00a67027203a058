#include "tracker/program/seeding.hpp"

#include "tracker/program/seeding_regions.hpp"

namespace cosim::tracker::program {

step::Seeding read_seeding(const scene::Reader& r, const std::filesystem::path& folder, double mesh_volume) {
  using scene::Range;
  step::Seeding s;
  s.mass = r.number("mass", Range::above(0));
  s.weight = r.number("weight", 1.0, Range::above(0));
  s.seed = static_cast<std::uint64_t>(r.integer("seed", 1, Range::at_least(0)));
  if (r.has("regions")) {
    for (const char* key : {"per_cell", "total", "temperature", "drift"})
      if (r.has(key)) r.fail(key, "not with regions: each region gives its number_density, temperature and velocity");
    s.regions = read_seed_regions(r, folder, mesh_volume, s.weight);
  } else {
    if (r.has("per_cell") == r.has("total")) r.fail("per_cell", "give exactly one of per_cell, total and regions");
    if (r.has("per_cell")) s.per_cell = r.integer("per_cell", Range::at_least(0));
    if (r.has("total")) s.total = r.integer("total", Range::at_least(0));
    s.temperature = r.number("temperature", Range::at_least(0));
    const scene::Vec3 drift = r.vec3("drift", scene::Vec3{0, 0, 0});
    s.drift = {drift[0], drift[1], drift[2]};
  }
  r.finish();
  return s;
}

}  // namespace cosim::tracker::program
