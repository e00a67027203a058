#include "tracker/step/collide.hpp"

namespace cosim::tracker::step {

CellCollider::CellCollider(const mesh::Mesh& mesh, const Collisions& collisions, double temperature, double weight,
                           std::uint64_t seed)
    : mesh_(mesh),
      collisions_(collisions),
      weight_(weight),
      cells_(static_cast<std::size_t>(mesh.cell_count()),
             {dsmc::initial_sigma_g_max(collisions.model, temperature), 0.0}),
      rng_(dsmc::make_rng(seed)) {}

std::int64_t CellCollider::collide(tracking::Swarm& swarm, double dt) {
  std::int64_t collisions = 0;
  for (std::size_t first = 0; first < swarm.size();) {
    const Index cell = swarm.cell(first);
    std::size_t end = first;
    velocities_.clear();
    positions_.clear();
    for (; end < swarm.size() && swarm.cell(end) == cell; ++end) {
      const tracking::Particle p = swarm.particle(end);
      velocities_.push_back(p.v);
      if (collisions_.nearest) positions_.push_back(p.x);
    }
    if (velocities_.size() >= 2) {
      auto& state = cells_[static_cast<std::size_t>(cell)];
      const double volume = mesh_.volume[static_cast<std::size_t>(cell)];
      const dsmc::CellCollisions done =
          collisions_.nearest
              ? dsmc::collide_cell_nearest(velocities_, positions_, collisions_.model, state, volume, weight_, dt, rng_)
              : dsmc::collide_cell(velocities_, collisions_.model, state, volume, weight_, dt, rng_);
      collisions += done.collisions;
      if (done.collisions > 0)
        for (std::size_t k = first; k < end; ++k) {
          tracking::Particle p = swarm.particle(k);
          p.v = velocities_[k - first];
          swarm.set(k, p);
        }
    }
    first = end;
  }
  return collisions;
}

}  // namespace cosim::tracker::step
