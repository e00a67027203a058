#include "tracker/tracking/sampling.hpp"

#include <algorithm>

namespace cosim::tracker {

CellSampler::CellSampler(const Mesh& mesh)
    : volume_(mesh.volume), count_(volume_.size(), 0.0), square_(volume_.size(), 0.0), sum_(volume_.size(), Vec3::Zero()) {}

void CellSampler::sample(const Swarm& swarm) {
  for (std::size_t i = 0; i < swarm.size(); ++i) {
    const Particle p = swarm.particle(i);
    const auto c = static_cast<std::size_t>(p.cell);
    count_[c] += 1.0;
    sum_[c] += p.v;
    square_[c] += p.v.squaredNorm();
  }
  ++samples_;
}

CellMoments CellSampler::moments(Index cell, double mass, double weight) const {
  const auto c = static_cast<std::size_t>(cell);
  CellMoments m;
  if (samples_ == 0 || count_[c] == 0.0) return m;
  m.count = count_[c] / samples_;
  m.number_density = m.count * weight / volume_[c];
  m.velocity = sum_[c] / count_[c];
  m.temperature = std::max(0.0, mass * (square_[c] / count_[c] - m.velocity.squaredNorm()) / (3.0 * boltzmann));
  m.pressure = m.number_density * boltzmann * m.temperature;
  return m;
}

void CellSampler::reset() {
  std::fill(count_.begin(), count_.end(), 0.0);
  std::fill(square_.begin(), square_.end(), 0.0);
  std::fill(sum_.begin(), sum_.end(), Vec3::Zero());
  samples_ = 0;
}

}  // namespace cosim::tracker
