// The work a scene gives cosim-tracker, for `--check --work` (participant/work_report.hpp).
#pragma once

#include "coupler/participant/work_report.hpp"
#include "coupler/scene/scene.hpp"
#include "tracker/program/scene_tracker.hpp"

namespace cosim::tracker::program {

// per_step {particles: the simulators at the start, crossings: about how many cell faces they
// cross in a step, cells: the mesh's cells}, held {particles, cells};
// grows when an inflow adds particles as the run goes. frame_bytes: the cell fields of
// cell_fields.hpp (8 float64 per cell) and, with particle_output, the particles' point set
// (particle_dump.hpp) at the start's count, averaged over the frames that carry it.
// `setup` is read_tracker(scene)'s on one rank, obstacles placed where the scene puts them.
participant::WorkReport tracker_work(const scene::Scene& scene, const TrackerScene& setup);

}  // namespace cosim::tracker::program
