// cosim-fluid as a participant: the Navier-Stokes flow around the scene's bodies, advanced
// window by window. It needs the bodies' poses and velocities and provides the
// hydrodynamic force and torque on each (protocol::kForceWidth values per body) and, with the
// immersed boundary, their response tensors (body_responses.hpp).
#pragma once

#include <memory>

#include "fluid/program/scene_fluid.hpp"
#include "coupler/participant/solver.hpp"

namespace cosim::fluid::program {

class FluidSolver final : public participant::Solver {
 public:
  // Prescribed: standalone, the bodies follow the scene's prescribed motion (not the
  // inputs) and the outputs carry their poses too.
  explicit FluidSolver(bool prescribed = false);
  ~FluidSolver() override;

  participant::Outputs initialise(const scene::Scene& scene, const std::string& name,
                                  const std::vector<participant::PoseRow>& poses,
                                  const std::vector<double>& state) override;
  // Subcycles with the flow's adaptive dt to exactly w.t1; before each step the bodies are
  // placed where they are at the step's end (inputs interpolated linearly in the window,
  // or held where no inputs come).
  participant::Outputs advance(const participant::Window& w, const participant::Inputs& in) override;
  // NavierStokes::state(): the bodies need none, they are placed anew every step.
  std::vector<double> state() const override;
  void restore(const std::vector<double>& state) override;
  // Cell-centred velocity, pressure and alpha (cell_fields.hpp), whole on rank 0; collective.
  field::FieldFrame fields() const override;

  const fluid::navier_stokes::NavierStokes& flow() const;
  // The steps taken on this rank so far, and the seconds of each stage of them summed.
  std::size_t steps() const { return steps_; }
  const fluid::navier_stokes::StageSeconds& stage_seconds() const { return stage_seconds_; }

 private:
  struct Flow;
  std::vector<participant::PoseRow> poses_at(const participant::Window& w, const participant::Inputs& in,
                                             double t) const;
  void place(const std::vector<participant::PoseRow>& poses);
  std::vector<participant::ForceRow> forces() const;  // per body: the loads of the flow as it is
  // Per body the response of those loads (body_responses.hpp) after the window whose bodies
  // started at `start` (empty: no window yet) and are now at poses_; none for the staircase.
  std::vector<participant::ResponseRow> responses(const std::vector<participant::PoseRow>& start,
                                                  const std::vector<participant::ForceRow>& loads);

  bool prescribed_;
  FluidSetup setup_;
  std::unique_ptr<Flow> flow_;
  std::vector<participant::PoseRow> poses_;  // where the bodies are now
  std::size_t steps_ = 0;
  fluid::navier_stokes::StageSeconds stage_seconds_;
};

}  // namespace cosim::fluid::program
