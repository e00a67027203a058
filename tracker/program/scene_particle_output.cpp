#include "tracker/program/scene_particle_output.hpp"

#include "coupler/field/field_frame.hpp"

namespace cosim::tracker::program {

std::optional<ParticleOutput> read_particle_output(const scene::Reader& options, const scene::Scene& scene,
                                                   const tracking::Obstacles& obstacles) {
  if (!options.has("particle_output")) return std::nullopt;
  const int fields_every = scene.output.fields_every;
  if (fields_every == 0)
    options.fail("particle_output",
                 "particles are written with the fields, and output.fields_every is 0 (none in a "
                 "coupled run, the start and the end alone standalone): set output.fields_every");
  const scene::Reader r = options.map("particle_output");
  ParticleOutput o;
  o.every = r.integer("every", fields_every, scene::Range::at_least(1));
  if (o.every % fields_every != 0)
    r.fail("every", "particles are written with the fields: give a multiple of output.fields_every (" +
                        std::to_string(fields_every) + ")");
  o.fraction = r.number("fraction", 1.0, scene::Range::left_open(0, 1));
  o.seed = static_cast<std::uint64_t>(r.integer("seed", 0, scene::Range::at_least(0)));
  r.finish();
  for (int i = 0; i < obstacles.count(); ++i)
    if (const std::string& name = obstacles.object(i).name; !field::dataset_name(state_attribute(name)))
      options.fail("particle_output", "obstacle '" + name + "' cannot name the particles' attribute " +
                                          state_attribute(name) + " (no '/' or control characters)");
  return o;
}

}  // namespace cosim::tracker::program
