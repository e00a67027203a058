#include "coupler/estimate/run_record.hpp"

#include "coupler/estimate/estimate.hpp"
#include "coupler/scene/plan.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>

namespace cosim::estimate {

std::string scene_key(const scene::Scene& scene) {
  std::uint64_t hash = 14695981039346656037ull;  // FNV-1a: stable across builds and hosts
  for (const unsigned char c : scene.text) hash = (hash ^ c) * 1099511628211ull;
  return fmt::format("{} {:016x}", std::filesystem::absolute(scene.file).lexically_normal().string(), hash);
}

RunRecord run_record(const scene::Scene& scene, const std::map<std::string, ProgramWork>& work, const RunTotals& totals,
                     const std::string& build) {
  RunRecord r;
  r.scene = scene_key(scene);
  r.build = build;
  r.calibration = std::getenv(kCalibrationEnv) != nullptr;
  r.windows = totals.windows;
  r.iterations = totals.iterations;
  r.wall_seconds = totals.wall_seconds;
  r.disk_bytes = totals.disk_bytes;
  const bool serial = scene::is_serial(scene.coupling.scheme);
  double programs = 0;
  for (const auto& [name, seconds] : totals.seconds) {
    Observation o;
    if (work.contains(name)) {
      o.per_step = work.at(name).per_step;
      o.held = work.at(name).held;
    }
    o.steps = totals.steps.contains(name) ? totals.steps.at(name) : 0.0;
    o.seconds = seconds;
    o.peak_bytes = totals.peak_bytes.contains(name) ? totals.peak_bytes.at(name) : 0.0;
    r.programs[name] = o;
    programs = serial ? programs + seconds : std::max(programs, seconds);
  }
  Observation coupler;
  coupler.per_step = coupler_work(scene, scene::plan_participants(scene).start, work, totals.iterations);
  coupler.steps = 1;
  coupler.seconds = std::max(0.0, totals.wall_seconds - programs);
  r.programs[kCoupler] = coupler;
  return r;
}

}  // namespace cosim::estimate
