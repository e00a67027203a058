#include "tracker/tracking/sampling.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>
#include <string>

namespace cosim::tracker {

CellSampler::CellSampler(const Mesh& mesh) : CellSampler(mesh.volume) {}

CellSampler::CellSampler(std::vector<double> volume)
    : volume_(std::move(volume)),
      count_(volume_.size(), 0.0),
      sum_(volume_.size(), Vec3::Zero()),
      cubic_(volume_.size(), Vec3::Zero()),
      square_(volume_.size(), Eigen::Matrix3d::Zero()) {}

void CellSampler::sample(const Swarm& swarm) {
  for (std::size_t i = 0; i < swarm.size(); ++i) {
    const Particle p = swarm.particle(i);
    const auto c = static_cast<std::size_t>(p.cell);
    count_[c] += 1.0;
    sum_[c] += p.v;
    square_[c] += p.v * p.v.transpose();
    cubic_[c] += p.v.squaredNorm() * p.v;
  }
  ++samples_;
}

CellMoments CellSampler::moments(Index cell, double mass, double weight) const {
  const auto c = static_cast<std::size_t>(cell);
  CellMoments m;
  if (samples_ == 0 || count_[c] == 0.0) return m;
  m.count = count_[c] / samples_;
  m.number_density = m.count * weight / volume_[c];
  const Vec3& u = m.velocity = sum_[c] / count_[c];
  const Eigen::Matrix3d second = square_[c] / count_[c];  // <v v^T>
  m.stress = m.number_density * mass * (second - u * u.transpose());
  m.temperature = std::max(0.0, m.stress.trace() / (3.0 * m.number_density * boltzmann));
  m.pressure = m.number_density * boltzmann * m.temperature;
  // <|c|^2 c> = <|v|^2 v> - <|v|^2> u - 2 <v v^T> u + 2 |u|^2 u.
  const Vec3 peculiar = cubic_[c] / count_[c] - second.trace() * u - 2.0 * second * u + 2.0 * u.squaredNorm() * u;
  m.heat_flux = 0.5 * m.number_density * mass * peculiar;
  return m;
}

void CellSampler::reset() {
  std::fill(count_.begin(), count_.end(), 0.0);
  std::fill(sum_.begin(), sum_.end(), Vec3::Zero());
  std::fill(cubic_.begin(), cubic_.end(), Vec3::Zero());
  std::fill(square_.begin(), square_.end(), Eigen::Matrix3d::Zero());
  samples_ = 0;
}

std::vector<double> CellSampler::sums() const {
  std::vector<double> out{static_cast<double>(samples_)};
  out.reserve(1 + kSumsPerCell * count_.size());
  for (std::size_t c = 0; c < count_.size(); ++c) {
    out.push_back(count_[c]);
    out.insert(out.end(), sum_[c].begin(), sum_[c].end());
    out.insert(out.end(), square_[c].data(), square_[c].data() + 9);
    out.insert(out.end(), cubic_[c].begin(), cubic_[c].end());
  }
  return out;
}

void CellSampler::set_sums(std::span<const double> sums) {
  if (sums.size() != 1 + kSumsPerCell * count_.size())
    throw std::invalid_argument("CellSampler::set_sums: " + std::to_string(sums.size()) + " values for " +
                                std::to_string(count_.size()) + " cells");
  samples_ = static_cast<int>(sums[0]);
  for (std::size_t c = 0; c < count_.size(); ++c) {
    const double* s = sums.data() + 1 + kSumsPerCell * c;
    count_[c] = s[0];
    sum_[c] = Vec3(s + 1);
    square_[c] = Eigen::Matrix3d(s + 4);
    cubic_[c] = Vec3(s + 13);
  }
}

}  // namespace cosim::tracker
