// What a program must offer to take part in a coupled run. The adapter of each program
// implements this over its library; run_participant() does all the talking.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "coupler/field/field_frame.hpp"
#include "coupler/participant/body_rows.hpp"
#include "coupler/scene/scene.hpp"

namespace cosim::participant {

struct Window {
  std::uint64_t index = 0;
  std::uint32_t iteration = 1;  // > 1: an implicit scheme repeats the window
  double t0 = 0.0;
  double t1 = 0.0;
};

// The coupler's values at the window's start and end, a row per body in scene order.
// Poses are instants: a solver evaluates them at s in
// [t0, t1] by linear interpolation (lerp(), below). The forces of cosim-fluid and
// cosim-tracker are the window's means (impulse over length), which cosim-rigidbody holds
// constant over the window; the oscillator doubles send instants and interpolate them.
// Where the scheme has no newer value yet, start and end are equal (the first participant
// of serial-explicit, everyone in parallel-explicit): held constant, first order. Implicit
// schemes converge the end value.
// A participant that needs fields gets another's (the fluid's) as committed at t0, the
// same in every iteration of the window: held constant over it, explicit, first order.
// With the forces may come the response tensors of the newest of them (the end value),
// when the providers of the forces send them: how those forces change with the bodies'
// motion (body_rows.hpp).
struct Inputs {
  std::vector<PoseRow> poses_start, poses_end;
  std::vector<ForceRow> forces_start, forces_end;
  std::vector<ResponseRow> responses;
  std::optional<field::FieldFrame> fields;  // none unless the participant needs fields
};

// The value at s in [w.t0, w.t1] of an input that goes linearly from start to end.
inline double lerp(double start, double end, const Window& w, double s) {
  return w.t1 > w.t0 ? start + (s - w.t0) / (w.t1 - w.t0) * (end - start) : end;
}

struct Outputs {
  std::vector<PoseRow> poses;    // if the solver provides poses
  std::vector<ForceRow> forces;  // if the solver provides forces
  double substeps = 0;
  std::vector<ResponseRow> responses = {};  // with the forces, if the solver measures them (else empty)
};

class Solver {
 public:
  virtual ~Solver() = default;
  // Set up from the scene (its own section: scene.participant(name)); `state` is
  // non-empty when resuming a run. Returns the outputs at the start time.
  virtual Outputs initialise(const scene::Scene& scene, const std::string& name, const std::vector<PoseRow>& poses,
                             const std::vector<double>& state) = 0;
  // From the state at w.t0, subcycle to exactly w.t1.
  virtual Outputs advance(const Window& w, const Inputs& in) = 0;
  // Everything needed to continue from here: used for rollback and checkpoints.
  virtual std::vector<double> state() const = 0;
  virtual void restore(const std::vector<double>& state) = 0;
  // The grid fields to write at output times now; no fields: nothing is written.
  virtual field::FieldFrame fields() const { return {}; }
  // A participant that needs fields names those it uses, so that only they cross the
  // wire; none named: the whole frame.
  virtual std::vector<std::string> wanted_fields() const { return {}; }
};

}  // namespace cosim::participant
