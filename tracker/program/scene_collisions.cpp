#include "tracker/program/scene_collisions.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>

#include "tracker/dsmc/species.hpp"

namespace cosim::tracker::program {

std::optional<step::Collisions> read_collisions(const scene::Reader& options, double mass) {
  if (!options.has("collisions")) return std::nullopt;
  const scene::Reader r = options.map("collisions");
  const dsmc::SpeciesTable table = dsmc::read_species(dsmc::default_species_file());
  const std::string name = r.string("species");
  if (!table.contains(name)) {
    std::string known;
    for (const auto& [species, _] : table.all()) known += (known.empty() ? "" : ", ") + species;
    r.fail("species", "not in " + table.file().string() + " (it has " + known + ")");
  }
  const dsmc::Species& species = table.at(name);
  constexpr std::array kModels{"hard_sphere", "vhs", "vss"};
  const auto model = static_cast<dsmc::Model>(r.choice("model", kModels));
  constexpr std::array kSelections{"uniform", "nearest"};
  const bool nearest = r.choice("selection", kSelections, 0) == 1;
  r.finish();
  if (std::abs(mass - species.mass) > 1e-6 * species.mass)
    r.fail("species",
           fmt::format("the particles' mass {:g} kg is not {}'s {:g} kg (particles.mass)", mass, name, species.mass));
  return step::Collisions{dsmc::CollisionModel::from_species(species, model), nearest};
}

}  // namespace cosim::tracker::program
