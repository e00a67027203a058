#include "tracker/tracking/sampling.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

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

std::vector<double> CellSampler::sums() const {
  std::vector<double> out{static_cast<double>(samples_)};
  out.reserve(1 + 5 * count_.size());
  for (std::size_t c = 0; c < count_.size(); ++c) out.insert(out.end(), {count_[c], square_[c], sum_[c].x(), sum_[c].y(), sum_[c].z()});
  return out;
}

void CellSampler::set_sums(std::span<const double> sums) {
  if (sums.size() != 1 + 5 * count_.size())
    throw std::invalid_argument("CellSampler::set_sums: " + std::to_string(sums.size()) + " values for " +
                                std::to_string(count_.size()) + " cells");
  samples_ = static_cast<int>(sums[0]);
  for (std::size_t c = 0; c < count_.size(); ++c) {
    const double* s = sums.data() + 1 + 5 * c;
    count_[c] = s[0];
    square_[c] = s[1];
    sum_[c] = {s[2], s[3], s[4]};
  }
}

}  // namespace cosim::tracker
