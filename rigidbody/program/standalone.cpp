#include "rigidbody/program/standalone.hpp"

#include <spdlog/spdlog.h>

#include <cstdio>

#include "coupler/participant/stage_summary.hpp"
#include "coupler/participant/standalone.hpp"
#include "rigidbody/program/adapter.hpp"
#include "coupler/scene/unused_materials.hpp"

namespace cosim::rigidbody::program {

void run_standalone(const std::filesystem::path& scene_file, std::filesystem::path output) {
  const scene::Scene scene = scene::load_scene(scene_file);
  // Coupled, the coupler says this once for every program; alone, this program is the one that reports.
  for (const auto& w : scene::unused_materials(scene)) spdlog::warn("{}", w);
  RigidSolver solver;
  participant::run_standalone(scene, solver, "rigidbody", std::move(output));
  std::fprintf(stderr, "cosim-rigidbody: %ld substeps: %s\n", solver.substeps(),
               participant::stage_summary(world::kStageNames, solver.stage_seconds().all()).c_str());
}

}  // namespace cosim::rigidbody::program
