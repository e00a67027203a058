#pragma once
// Time averages per cell of what the simulators carry (Bird 1994, 1.4): number density,
// mean velocity, translational temperature, pressure tensor and heat flux, from sums over
// the samples taken (one per step), so a cell with few simulators per step still averages
// right.

#include "tracker/tracking/swarm.hpp"

#include <array>
#include <span>
#include <vector>

namespace cosim::tracker::tracking {

struct CellMoments {
  double count = 0.0;            // simulators, mean over the samples
  double number_density = 0.0;   // real molecules per m^3
  Vec3 velocity = Vec3::Zero();  // mean, m/s
  double temperature = 0.0;      // m (<|v|^2> - |<v>|^2) / (3 k), K; 0 where nobody passed
  double pressure = 0.0;         // n k T, Pa
  // The pressure tensor n m <c c^T> (c = v - velocity), Pa: its trace / 3 is `pressure`,
  // -stress(0, 1) the shear stress tau_xy on planes normal to y.
  Eigen::Matrix3d stress = Eigen::Matrix3d::Zero();
  Vec3 heat_flux = Vec3::Zero();  // translational: n m <|c|^2 c> / 2, W/m^2
};

class CellSampler {
 public:
  explicit CellSampler(const mesh::Mesh& mesh);

  // In a DSMC step, sample after the move and again after the collisions for the stress and
  // heat flux: either alone is off by about dt / (2 mu / p) (README, "When to sample").
  void sample(const Swarm& swarm);
  int samples() const { return samples_; }
  // `mass` of a molecule (kg) and `weight` (molecules per simulator).
  CellMoments moments(Index cell, double mass, double weight) const;
  // The same from one cell's kSumsPerCell sums (as sums() lays them out) over `samples`
  // samples, in a cell of `volume` (m^3): for sums added up elsewhere.
  static CellMoments moments(std::span<const double> sums, int samples, double volume, double mass, double weight);
  // Starts a new average.
  void reset();
  static constexpr std::size_t kSumsPerCell = 1 + 3 + 9 + 3;
  // The sums as one array: the sample count, then per cell (kSumsPerCell values) its
  // simulator count and the sums of v, v v^T (column-major) and |v|^2 v. For rollback,
  // checkpoints and sums over ranks.
  std::vector<double> sums() const;
  // std::invalid_argument unless `sums` has the layout of sums() for this mesh.
  void set_sums(std::span<const double> sums);
  // One cell's kSumsPerCell sums as sums() lays them out; add_sums() adds such sums (of the
  // same cell, sampled on another rank) to the cell's.
  std::array<double, kSumsPerCell> cell_sums(Index cell) const;
  void add_sums(Index cell, std::span<const double> sums);

 private:
  std::vector<double> volume_;
  // Sums of 1, v, v v^T and |v|^2 v over the samples.
  std::vector<double> count_;
  std::vector<Vec3> sum_, cubic_;
  std::vector<Eigen::Matrix3d> square_;
  int samples_ = 0;
};

}  // namespace cosim::tracker::tracking
