#include "tracker/tracking/sampling.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace cosim::tracker::tracking {

CellSampler::CellSampler(const mesh::Mesh& mesh)
    : volume_(mesh.volume),
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

namespace {

CellMoments moments_of(double count, const Vec3& sum, const Eigen::Matrix3d& square, const Vec3& cubic, int samples,
                       double volume, double mass, double weight) {
  CellMoments m;
  if (samples == 0 || count == 0.0) return m;
  m.count = count / samples;
  m.number_density = m.count * weight / volume;
  const Vec3& u = m.velocity = sum / count;
  const Eigen::Matrix3d second = square / count;  // <v v^T>
  m.stress = m.number_density * mass * (second - u * u.transpose());
  m.temperature = std::max(0.0, m.stress.trace() / (3.0 * m.number_density * boltzmann));
  m.pressure = m.number_density * boltzmann * m.temperature;
  // <|c|^2 c> = <|v|^2 v> - <|v|^2> u - 2 <v v^T> u + 2 |u|^2 u.
  const Vec3 peculiar = cubic / count - second.trace() * u - 2.0 * second * u + 2.0 * u.squaredNorm() * u;
  m.heat_flux = 0.5 * m.number_density * mass * peculiar;
  return m;
}

}  // namespace

CellMoments CellSampler::moments(Index cell, double mass, double weight) const {
  const auto c = static_cast<std::size_t>(cell);
  return moments_of(count_[c], sum_[c], square_[c], cubic_[c], samples_, volume_[c], mass, weight);
}

CellMoments CellSampler::moments(std::span<const double> sums, int samples, double volume, double mass, double weight) {
  if (sums.size() != kSumsPerCell)
    throw std::invalid_argument("CellSampler::moments: " + std::to_string(sums.size()) + " sums of a cell");
  return moments_of(sums[0], Vec3(sums.data() + 1), Eigen::Matrix3d(sums.data() + 4), Vec3(sums.data() + 13), samples,
                    volume, mass, weight);
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
  for (Index c = 0; c < static_cast<Index>(count_.size()); ++c) {
    const std::array<double, kSumsPerCell> cell = cell_sums(c);
    out.insert(out.end(), cell.begin(), cell.end());
  }
  return out;
}

std::array<double, CellSampler::kSumsPerCell> CellSampler::cell_sums(Index cell) const {
  const auto c = static_cast<std::size_t>(cell);
  std::array<double, kSumsPerCell> out{count_[c]};
  std::copy_n(sum_[c].data(), 3, out.begin() + 1);
  std::copy_n(square_[c].data(), 9, out.begin() + 4);
  std::copy_n(cubic_[c].data(), 3, out.begin() + 13);
  return out;
}

void CellSampler::add_sums(Index cell, std::span<const double> sums) {
  if (sums.size() != kSumsPerCell)
    throw std::invalid_argument("CellSampler::add_sums: " + std::to_string(sums.size()) + " sums of a cell");
  const auto c = static_cast<std::size_t>(cell);
  count_[c] += sums[0];
  sum_[c] += Vec3(sums.data() + 1);
  square_[c] += Eigen::Matrix3d(sums.data() + 4);
  cubic_[c] += Vec3(sums.data() + 13);
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

}  // namespace cosim::tracker::tracking
