// cosim-rigidbody as a coupled participant: the world advanced window by window under the
// coupler's forces. It provides poses and can take forces (the coupler sends them only
// when some participant produces them).
#pragma once

#include <memory>

#include "participant/solver.hpp"
#include "rigidbody/world/world.hpp"

namespace cosim::program {

class RigidSolver final : public participant::Solver {
 public:
  participant::Outputs initialise(const scene::Scene& scene, const std::string& name,
                                  const std::vector<double>& poses, const std::vector<double>& state) override;
  participant::Outputs advance(const participant::Window& w, const participant::Inputs& in) override;
  // [time, then per body its 13 pose values (protocol::kPoseWidth)]. Restoring rebuilds the world, which drops the
  // contact graph and its warm-start impulses: the first substep after a rollback starts
  // the solver cold, so it is not bit-identical to a run that never rolled back.
  std::vector<double> state() const override;
  void restore(const std::vector<double>& state) override;

  const world::World& world() const { return *world_; }

 private:
  std::vector<double> poses() const;

  scene::Scene scene_;
  std::unique_ptr<world::World> world_;
  double time_ = 0.0;  // absolute; the world's own clock restarts at a restore
};

}  // namespace cosim::program
