// Tracer mode (participants.tracker.options.tracers), optional: the particles are tracers
// carried by a fluid's velocity field (tracker/tracers) instead of a gas.
//
//   tracers:
//     response_time: 0     # s; 0: massless (they move with the fluid), > 0: Stokes drag
//     substeps: 1          # segments per step
//     velocity: {file: runs/dfg-cylinder.h5}   # standalone: the last velocity field of
//                          # that run file (the fluid's, cell-centred); coupled runs get
//                          # the fluid's field from the coupler every window
//
// The particles section seeds them (temperature 0: all at the drift velocity). Collisions
// and inflow are the gas's: with tracers they are refused. Errors are scene::SceneError
// naming file, line, key and value.
#pragma once

#include <optional>

#include "coupler/scene/reader.hpp"
#include "coupler/scene/scene.hpp"
#include "tracker/step/gas_setup.hpp"

namespace cosim::tracker::program {

std::optional<step::Tracers> read_tracers(const scene::Reader& options, const scene::Scene& scene);

}  // namespace cosim::tracker::program
