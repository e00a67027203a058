// The work a scene gives cosim-rigidbody, for `--check --work` (participant/work_report.hpp):
// its step's cost grows with the bodies that move, its memory with every body it holds.
#pragma once

#include "coupler/participant/work_report.hpp"
#include "coupler/scene/scene.hpp"
#include "rigidbody/program/scene_world.hpp"

namespace cosim::rigidbody::program {

// per_step {bodies: the scene's bodies that are not fixed}; held {bodies: the scene's bodies
// and the domain faces made walls}; frame_bytes 0: the program writes no fields.
participant::WorkReport rigid_work(const scene::Scene& scene, const ProgramOptions& options);

}  // namespace cosim::rigidbody::program
