// The tracker's particles, or a sample of them (scene_particle_output.hpp), as the point set
// "particles" of its field frame, as SPARTA's `dump particle` writes them: positions, and per
// particle the attributes
//   velocity         (3, m/s)
//   cell             (1, integer): the global cell index, as in the frame's cell fields
//   state_<obstacle> (2, integer) per obstacle: its logical state, a 64-bit pattern with a bit
//                    per primitive the obstacle has in the particle's cell, bit i set = inside
//                    the cell's i-th (csg/state.hpp, bounding/cell_object.hpp; 0 in a cell
//                    where it has none), as the high and the low 32 bits (state = high * 2^32
//                    + low): float64 carries the frame and holds whole numbers exactly only
//                    up to 2^53
//   inside_<obstacle> (1, integer) per obstacle: 1 if that state puts the particle inside the
//                    obstacle (a permeable zone; never a wall), else 0
// The particles have no identity (SPARTA gives each a random id; here they are 40 bytes of
// position, velocity and cell), so the sample is chosen by a hash of the seed and the bits
// of the particle's position: the same particles on any number of ranks and in any storage
// order, about `fraction` of them wherever they are, but another sample at every write. A
// particle cannot be followed from one write to the next.
#pragma once

#include "coupler/field/field_frame.hpp"
#include "tracker/program/scene_particle_output.hpp"
#include "tracker/step/simulation.hpp"

namespace cosim::tracker::program {

inline constexpr char kParticleSet[] = "particles";

// The float64 values one particle takes in the set: x, y, z, velocity (3) and cell, and per
// obstacle its state (2) and inside.
constexpr std::size_t particle_values(std::size_t obstacles) { return 7 + 3 * obstacles; }

// Collective over the gas's ranks: rank 0 gets the chosen particles of every rank, in cell
// order and within a cell by position (the same set in the same order on any rank count),
// the other ranks a set without points.
field::PointSet particle_set(const step::Simulation& gas, const ParticleOutput& output);

}  // namespace cosim::tracker::program
