// cosim-rigidbody as a coupled participant: the world advanced window by window under the
// coupler's forces. It provides poses and can take forces (the coupler sends them only
// when some participant produces them).
#pragma once

#include <memory>

#include "coupler/participant/solver.hpp"
#include "rigidbody/program/fluid_response.hpp"
#include "rigidbody/program/virtual_mass.hpp"
#include "rigidbody/world/world.hpp"

namespace cosim::rigidbody::program {

class RigidSolver final : public participant::Solver {
 public:
  participant::Outputs initialise(const scene::Scene& scene, const std::string& name,
                                  const std::vector<participant::PoseRow>& poses,
                                  const std::vector<double>& state) override;
  participant::Outputs advance(const participant::Window& w, const participant::Inputs& in) override;
  // [time, per body its 13 pose values (protocol::kPoseWidth), with a virtual mass the
  // previous window's applied wrenches (VirtualMass::save), then the contact memory
  // (solver::ContactMemory::save)]: everything a substep carries to the next, so a rollback
  // repeats the windows bit for bit, warm starts included.
  std::vector<double> state() const override;
  void restore(const std::vector<double>& state) override;

  const world::World& world() const { return *world_; }
  // Since initialise(), over every window advanced (a repeated one counts again).
  long substeps() const { return substeps_; }
  const world::StageSeconds& stage_seconds() const { return stage_seconds_; }

 private:
  std::vector<participant::PoseRow> poses() const;

  scene::Scene scene_;
  std::unique_ptr<world::World> world_;
  VirtualMass virtual_mass_{0, 0};
  bool warned_virtual_mass_ = false;
  long substeps_ = 0;
  world::StageSeconds stage_seconds_;
};

}  // namespace cosim::rigidbody::program
