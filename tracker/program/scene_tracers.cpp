#include "tracker/program/scene_tracers.hpp"

#include "tracker/program/velocity_input.hpp"

namespace cosim::tracker::program {

std::optional<step::Tracers> read_tracers(const scene::Reader& options, const scene::Scene& scene) {
  if (!options.has("tracers")) return std::nullopt;
  const scene::Reader r = options.map("tracers");
  step::Tracers t;
  t.model.response_time = r.number("response_time", 0.0, scene::Range::at_least(0));
  t.model.substeps = static_cast<int>(r.integer("substeps", 1, scene::Range::at_least(1)));
  if (r.has("velocity")) {
    const scene::Reader v = r.map("velocity");
    const std::filesystem::path file = scene.folder / v.string("file");
    v.finish();
    try {
      t.velocity = read_velocity(file);
    } catch (const std::exception& e) {
      v.fail("file", e.what());
    }
  }
  r.finish();
  return t;
}

}  // namespace cosim::tracker::program
