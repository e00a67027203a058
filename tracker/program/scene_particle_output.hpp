// The particles written with the fields (participants.tracker.options.particle_output),
// optional, as SPARTA's `dump particle` writes them:
//
//   particle_output:
//     every: 10        # windows between writes; optional, default output.fields_every
//     fraction: 0.1    # optional, in (0, 1], default 1: a sample of about that fraction
//     seed: 1          # optional, default 0: another seed, another sample
//
// The particles go into the field frame as the point set "particles" (particle_dump.hpp),
// so they are written only with the fields: after every `every` windows, at the start and
// after the last window, as output.fields_every writes the fields. `every` must therefore
// be a multiple of output.fields_every, and output.fields_every must not be 0 (a coupled
// run then writes no fields at all): a scene that asks for particles the fields would not
// carry is refused rather than silently thinned. Errors are scene::SceneError naming file,
// line, key and value.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "coupler/scene/reader.hpp"
#include "tracker/tracking/obstacles.hpp"

namespace cosim::tracker::program {

struct ParticleOutput {
  int every = 1;
  double fraction = 1.0;
  std::uint64_t seed = 0;
  // Whether the particles are written after `done` of `windows` windows.
  bool at(std::uint64_t done, std::uint64_t windows) const {
    return done % static_cast<std::uint64_t>(every) == 0 || done == windows;
  }
};

// The attributes that hold a particle's logical state for an obstacle and whether it is
// inside (particle_dump.hpp).
inline std::string state_attribute(const std::string& obstacle) { return "state_" + obstacle; }
inline std::string inside_attribute(const std::string& obstacle) { return "inside_" + obstacle; }

// None without the key; refuses, besides bad values, an obstacle whose name cannot name its
// attributes (a '/' or a control character in it).
std::optional<ParticleOutput> read_particle_output(const scene::Reader& options, const scene::Scene& scene,
                                                   const tracking::Obstacles& obstacles);

}  // namespace cosim::tracker::program
