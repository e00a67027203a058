#pragma once
// How the bench keeps its particles between moves. move() takes a tracker::Particle
// (56 bytes: two Vec3 and the cell, padded to 8); the compact record keeps the velocity in
// float (40 bytes) and converts around each move. That is exact in this deck: the only
// velocity change is a specular reflection on an axis-aligned wall, which flips the sign of
// one component, so a velocity that starts as floats stays floats, and the kinetic energy is
// conserved to the last bit (the energy check says so).

#include "tracker/tracking/particle.hpp"

#include <vector>

namespace cosim::bench {

struct CompactParticle {
  double x[3];
  float v[3];
  tracker::Index cell;
};
static_assert(sizeof(CompactParticle) == 40);

inline tracker::Particle load(const tracker::Particle& p) { return p; }
inline void store(tracker::Particle& to, const tracker::Particle& p) { to = p; }

inline tracker::Particle load(const CompactParticle& c) {
  return {{c.x[0], c.x[1], c.x[2]}, {c.v[0], c.v[1], c.v[2]}, c.cell};
}
inline void store(CompactParticle& to, const tracker::Particle& p) {
  to = {{p.x[0], p.x[1], p.x[2]},
        {static_cast<float>(p.v[0]), static_cast<float>(p.v[1]), static_cast<float>(p.v[2])},
        p.cell};
}

template <class T>
std::vector<T> convert(const std::vector<tracker::Particle>& particles) {
  std::vector<T> out(particles.size());
  for (std::size_t i = 0; i < particles.size(); ++i) store(out[i], particles[i]);
  return out;
}

// Counting sort by cell (stable), as SPARTA reorders its particles: consecutive particles
// then read the same faces. `scratch` is resized to the particles' size.
template <class T>
void sort_by_cell(std::vector<T>& items, std::vector<T>& scratch, tracker::Index cells) {
  std::vector<std::size_t> begin(static_cast<std::size_t>(cells) + 1, 0);
  for (const T& item : items) ++begin[static_cast<std::size_t>(item.cell) + 1];
  for (std::size_t c = 1; c < begin.size(); ++c) begin[c] += begin[c - 1];
  scratch.resize(items.size());
  for (const T& item : items) scratch[begin[static_cast<std::size_t>(item.cell)]++] = item;
  items.swap(scratch);
}

}  // namespace cosim::bench
