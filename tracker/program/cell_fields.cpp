#include "tracker/program/cell_fields.hpp"

namespace cosim::tracker::program {

std::vector<field::CellField> cell_fields(std::span<const tracking::CellMoments> moments,
                                          std::span<const double> count) {
  field::CellField mean_count{"mean_count", 1, {}}, density{"density", 1, {}}, velocity{"velocity", 3, {}},
      temperature{"temperature", 1, {}}, pressure{"pressure", 1, {}};
  // Sized once: a write of many cells holds these beside the moments.
  for (field::CellField* f : {&mean_count, &density, &velocity, &temperature, &pressure})
    f->values.reserve(moments.size() * static_cast<std::size_t>(f->components));
  for (const tracking::CellMoments& c : moments) {
    mean_count.values.push_back(c.count);
    density.values.push_back(c.number_density);
    velocity.values.insert(velocity.values.end(), {c.velocity.x(), c.velocity.y(), c.velocity.z()});
    temperature.values.push_back(c.temperature);
    pressure.values.push_back(c.pressure);
  }
  return {{"count", 1, {count.begin(), count.end()}},
          std::move(mean_count),
          std::move(density),
          std::move(velocity),
          std::move(temperature),
          std::move(pressure)};
}

}  // namespace cosim::tracker::program
