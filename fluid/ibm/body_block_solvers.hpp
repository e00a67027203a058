#pragma once
// Each body's block of the forcing's system B (forcing_system.hpp) solved on its own: the
// preconditioner of B's Krylov solve, block Jacobi with one block per body. A block is
// factored (Cholesky where B is symmetric, by CHOLMOD where PETSc has SuiteSparse, LU
// otherwise, unless the options `-ibm_forcing_sub_*` say otherwise) when it first appears
// and kept, with its factors, for as long as its entries stay the same: a body that does
// not move (a container, a fixed sphere) is factored once, not at every step, unless
// another body comes to cover some of its markers. A block whose entries changed but not
// where they are (a body moved a little) keeps its ordering and symbolic factors and is
// factored numerically only. The solvers outlive the steps' systems.
#include <petscksp.h>

#include <cstddef>
#include <span>
#include <vector>

namespace cosim::fluid::ibm {

class BodyBlockSolvers {
 public:
  BodyBlockSolvers() = default;
  ~BodyBlockSolvers();
  BodyBlockSolvers(const BodyBlockSolvers&) = delete;
  BodyBlockSolvers& operator=(const BodyBlockSolvers&) = delete;

  // Takes the blocks of B's bodies whose values this rank holds (body b's rows
  // 3 first_marker[b] .. 3 first_marker[b + 1] - 1), keeping the solvers of blocks that
  // did not change and factoring the others; drops those of bodies no longer here.
  // `symmetric`: B is (the forcing spreads where it interpolates), so its blocks are
  // symmetric (and positive definite while no two markers' kernels coincide).
  void update(Mat B, std::span<const std::size_t> first_marker, bool symmetric);
  // y = x with each block's rows solved by its block (collective only through B's layout:
  // the blocks are this rank's).
  void apply(Vec x, Vec y) const;
  // The blocks factored from scratch since construction, and those factored again on the
  // same pattern.
  int factorizations() const { return factorizations_; }
  int refactorizations() const { return refactorizations_; }

 private:
  struct Block {
    std::size_t body = 0;
    PetscInt offset = 0;     // its first row among this rank's
    bool symmetric = false;  // factored as symmetric (Cholesky)
    Mat matrix = nullptr;
    KSP ksp = nullptr;
    Vec x = nullptr, y = nullptr;  // views of the rows in apply()
  };
  static void destroy(Block& block);
  static Block factored(std::size_t body, PetscInt offset, Mat matrix, bool symmetric);

  std::vector<Block> blocks_;
  int factorizations_ = 0, refactorizations_ = 0;
};

}  // namespace cosim::fluid::ibm
