#pragma once
// The right-hand sides of a step's viscous solves open as DMDA arrays, and with a body
// forcing the explicit estimate u~ beside them: written by the right-hand-side stage, read
// and changed by the forcing, closed before the solves read the vectors.
#include <petscdmda.h>

#include <array>

#include "fluid/body_forcing.hpp"
#include "fluid/grid.hpp"

namespace cosim::fluid {

class StepArrays {
 public:
  // rhs: global vectors of the component DMs; u~ is taken from the DMs' pools when
  // with_estimate.
  StepArrays(const Grid& grid, const std::array<Vec, 3>& rhs, bool with_estimate);
  ~StepArrays();
  StepArrays(const StepArrays&) = delete;
  StepArrays& operator=(const StepArrays&) = delete;

  const ForcingArrays& arrays() const { return arrays_; }
  bool with_estimate() const { return estimate_[0] != nullptr; }

 private:
  const Grid& grid_;
  std::array<Vec, 3> rhs_;
  std::array<Vec, 3> estimate_{};
  ForcingArrays arrays_;
};

}  // namespace cosim::fluid
