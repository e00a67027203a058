#pragma once
// StepResponse over NavierStokes's viscous solve and projection: two pooled vectors per
// component, taken at the first call (a forcing that asks for nothing costs nothing), the
// right-hand side kept open for the forcing to spread into.
#include <petscdmda.h>

#include <array>
#include <functional>

#include "fluid/bodies/body_forcing.hpp"
#include "fluid/grid/grid.hpp"

namespace cosim::fluid::navier_stokes {

class LinearResponse final : public bodies::StepResponse {
 public:
  // solve(rhs, change, keep): change = the viscous solve and projection of rhs; with keep
  // also added to the step's velocity and pressure.
  using Solve = std::function<void(const std::array<Vec, 3>& rhs, const std::array<Vec, 3>& change, bool keep)>;
  LinearResponse(const grid::Grid& grid, Solve solve);
  ~LinearResponse() override;
  LinearResponse(const LinearResponse&) = delete;
  LinearResponse& operator=(const LinearResponse&) = delete;

  const std::array<PetscScalar***, 3>& rhs() override;
  const std::array<PetscScalar***, 3>& change() override;
  void apply() override;

 private:
  void open();          // takes the vectors, opens rhs, zero
  void run(bool keep);  // closes both, solves, zeroes and reopens rhs
  void close_change();

  const grid::Grid& grid_;
  Solve solve_;
  bool open_ = false;
  std::array<Vec, 3> rhs_{}, change_{};
  std::array<PetscScalar***, 3> rhs_arrays_{}, change_arrays_{};
};

}  // namespace cosim::fluid::navier_stokes
