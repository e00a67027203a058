#pragma once
// The right-hand sides of a step's viscous solves open as DMDA arrays, and with a body
// forcing the explicit estimate u~ beside them: written by the right-hand-side stage, read
// and changed by the forcing, closed before the solves read the vectors.
#include <petscdmda.h>

#include <array>

#include "fluid/bodies/body_forcing.hpp"
#include "fluid/grid/grid.hpp"

namespace cosim::fluid::navier_stokes {

class StepArrays {
 public:
  // rhs: global vectors of the component DMs; u~ is taken from the DMs' pools when
  // with_estimate.
  StepArrays(const grid::Grid& grid, const std::array<Vec, 3>& rhs, bool with_estimate);
  ~StepArrays();
  StepArrays(const StepArrays&) = delete;
  StepArrays& operator=(const StepArrays&) = delete;

  const bodies::ForcingArrays& arrays() const { return arrays_; }
  bool with_estimate() const { return estimate_[0] != nullptr; }

 private:
  const grid::Grid& grid_;
  std::array<Vec, 3> rhs_;
  std::array<Vec, 3> estimate_{};
  bodies::ForcingArrays arrays_;
};

}  // namespace cosim::fluid::navier_stokes
