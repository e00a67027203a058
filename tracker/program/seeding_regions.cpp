#include "tracker/program/seeding_regions.hpp"

#include <cstdio>
#include <string>

#include "tracker/program/csg_shape.hpp"

namespace cosim::tracker::program {
namespace {

// More simulated particles than a region of a tracker run is meant to hold (40 bytes each:
// 40 GB); a real number density with the default weight of 1 asks for far more.
constexpr double kMostParticles = 1e9;

std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", x);
  return text;
}

}  // namespace

std::vector<step::SeedRegion> read_seed_regions(const scene::Reader& particles, const std::filesystem::path& folder,
                                                double mesh_volume, double weight) {
  using scene::Range;
  std::vector<step::SeedRegion> regions;
  for (const scene::Reader& r : particles.maps("regions")) {
    step::SeedRegion region{.shape = read_shape(r.map("region"), folder)};
    region.number_density = r.number("number_density", Range::above(0));
    if (const double most = region.number_density * mesh_volume / weight; most > kMostParticles)
      r.fail("number_density", "up to " + number(most) + " particles in the mesh's " + number(mesh_volume) +
                                   " m^3 at particles.weight " + number(weight) +
                                   ": give a weight (real molecules per simulated particle, default 1)");
    region.temperature = r.number("temperature", Range::at_least(0));
    const scene::Vec3 v = r.vec3("velocity", scene::Vec3{0, 0, 0});
    region.velocity = {v[0], v[1], v[2]};
    if (r.has("species"))
      r.fail("species", "the gas is one species, of particles.mass (and collisions.species): no mixtures");
    r.finish();
    regions.push_back(std::move(region));
  }
  if (regions.empty()) particles.fail("regions", "needs at least one region");
  return regions;
}

}  // namespace cosim::tracker::program
