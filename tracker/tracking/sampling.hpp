#pragma once
// Time averages per cell of what the simulators carry (Bird 1994, 1.4): number density,
// mean velocity, translational temperature and pressure, from sums over the samples taken
// (one per step), so a cell with few simulators per step still averages right.

#include "tracker/tracking/swarm.hpp"

#include <span>
#include <vector>

namespace cosim::tracker {

struct CellMoments {
  double count = 0.0;           // simulators, mean over the samples
  double number_density = 0.0;  // real molecules per m^3
  Vec3 velocity = Vec3::Zero(); // mean, m/s
  double temperature = 0.0;     // m (<|v|^2> - |<v>|^2) / (3 k), K; 0 where nobody passed
  double pressure = 0.0;        // n k T, Pa
};

class CellSampler {
 public:
  explicit CellSampler(const Mesh& mesh);

  void sample(const Swarm& swarm);
  int samples() const { return samples_; }
  // `mass` of a molecule (kg) and `weight` (molecules per simulator).
  CellMoments moments(Index cell, double mass, double weight) const;
  // Starts a new average.
  void reset();
  // The sums as one array: the sample count, then per cell its simulator count, sum of
  // |v|^2 and sum of v (x, y, z). For rollback, checkpoints and sums over ranks.
  std::vector<double> sums() const;
  // std::invalid_argument unless `sums` has the layout of sums() for this mesh.
  void set_sums(std::span<const double> sums);

 private:
  std::vector<double> volume_;
  std::vector<double> count_, square_;
  std::vector<Vec3> sum_;
  int samples_ = 0;
};

}  // namespace cosim::tracker
