#pragma once
// The forcing's linear system B g = r, B = I S: the impulses g spread and interpolated back
// at the markers (immersed_boundary.hpp). B is assembled once per step from the markers'
// kernels (MarkerStencils::products), on the markers' roots (marker_sharing.hpp) laid out
// by whole bodies, and solved by PETSc's conjugate gradients (GMRES where the markers
// spread from elsewhere than they interpolate, which makes B unsymmetric) preconditioned
// by each body's block solved exactly (block Jacobi, one block per body, Cholesky or LU;
// body_block_solvers.hpp): a body alone converges in one iteration and bodies whose
// kernels overlap (a cloud, a bed) in a few more, where sweeps through the grid
// preconditioned by B's diagonal did not reach the tolerance in 50 in a falling cloud. The
// blocks are the bodies on any number of ranks, so the iterations do not depend on the
// ranks. Options take the prefix `ibm_forcing_` (`-ibm_forcing_ksp_monitor`).
#include <petscksp.h>

#include <span>
#include <vector>

#include "fluid/ibm/body_block_solvers.hpp"
#include "fluid/ibm/marker_stencils.hpp"

namespace cosim::fluid::ibm {

// The roots this rank keeps: whole bodies' values (3 per marker, body b's markers numbered
// first_marker[b] .. first_marker[b + 1] - 1), about as many on each rank.
PetscInt roots_by_body(MPI_Comm comm, std::span<const std::size_t> first_marker);

class ForcingSystem {
 public:
  // B interpolating with `stencils` what is spread with `spreading` (the same markers;
  // `stencils` itself for the symmetric system), the stencils' sharing laid out by
  // roots_by_body(first_marker) (collective).
  // Each body's block is solved by `blocks` (which keeps a block's factors from the last
  // system while the block is unchanged) unless the options choose another preconditioner.
  ForcingSystem(const MarkerStencils& stencils, const MarkerStencils& spreading,
                std::span<const std::size_t> first_marker, BodyBlockSolvers& blocks);
  ~ForcingSystem();
  ForcingSystem(const ForcingSystem&) = delete;
  ForcingSystem& operator=(const ForcingSystem&) = delete;

  // Solves B g = r for the values this rank holds, from g as given, until the largest
  // |r - B g| is at most `tolerance` or after `max_iterations`; `residual` holds r on entry
  // and r - B g on return. Returns the iterations (collective).
  int solve(std::vector<double>& g, std::vector<double>& residual, double tolerance, int max_iterations) const;

 private:
  const MarkerStencils& stencils_;
  Mat B_ = nullptr;
  KSP ksp_ = nullptr;
  Vec rhs_ = nullptr, g_ = nullptr, work_ = nullptr, left_ = nullptr;
};

}  // namespace cosim::fluid::ibm
