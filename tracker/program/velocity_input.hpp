// The fluid's velocity for tracer mode, as a trilinear VelocityField at the fluid's cell
// centres: from the field frame the coupler forwards, or from a run file's last frame.
#pragma once

#include <filesystem>
#include <string>

#include "coupler/field/field_frame.hpp"
#include "tracker/tracers/velocity_field.hpp"

namespace cosim::tracker::program {

// The frame's cell-centred `velocity` (3 components) at the centres of its rectilinear
// grid. Throws std::runtime_error if the frame has no such field or its size is wrong.
tracers::VelocityField velocity_of(const field::FieldFrame& frame);

// The last velocity field `participant` wrote to the run file `file`
// (/fields/<participant>/grid and the highest /fields/<participant>/<window>/velocity).
// Throws std::runtime_error naming the file and what is missing.
tracers::VelocityField read_velocity(const std::filesystem::path& file, const std::string& participant = "fluid");

}  // namespace cosim::tracker::program
