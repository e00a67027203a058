#include "fluid/ibm/body_block_solvers.hpp"

#include <algorithm>

#include "fluid/petsc_check.hpp"

namespace cosim::fluid::ibm {

namespace {

// Whether two sequential AIJ matrices have their entries in the same places.
bool same_pattern(Mat a, Mat b) {
  PetscInt m = 0, n = 0;
  const PetscInt *ai = nullptr, *aj = nullptr, *bi = nullptr, *bj = nullptr;
  PetscBool done_a = PETSC_FALSE, done_b = PETSC_FALSE;
  COSIM_PETSC(MatGetRowIJ(a, 0, PETSC_FALSE, PETSC_FALSE, &m, &ai, &aj, &done_a));
  COSIM_PETSC(MatGetRowIJ(b, 0, PETSC_FALSE, PETSC_FALSE, &n, &bi, &bj, &done_b));
  const bool same = done_a && done_b && m == n && std::equal(ai, ai + m + 1, bi) && std::equal(aj, aj + ai[m], bj);
  COSIM_PETSC(MatRestoreRowIJ(a, 0, PETSC_FALSE, PETSC_FALSE, &m, &ai, &aj, &done_a));
  COSIM_PETSC(MatRestoreRowIJ(b, 0, PETSC_FALSE, PETSC_FALSE, &n, &bi, &bj, &done_b));
  return same;
}

}  // namespace

BodyBlockSolvers::~BodyBlockSolvers() {
  for (Block& block : blocks_) destroy(block);
}

void BodyBlockSolvers::destroy(Block& block) {
  KSPDestroy(&block.ksp);
  MatDestroy(&block.matrix);
  VecDestroy(&block.x);
  VecDestroy(&block.y);
}

BodyBlockSolvers::Block BodyBlockSolvers::factored(std::size_t body, PetscInt offset, Mat matrix, bool symmetric) {
  Block block{body, offset, symmetric, matrix};
  PetscInt size = 0;
  COSIM_PETSC(MatGetLocalSize(matrix, &size, nullptr));
  COSIM_PETSC(VecCreateSeqWithArray(PETSC_COMM_SELF, 1, size, nullptr, &block.x));
  COSIM_PETSC(VecCreateSeqWithArray(PETSC_COMM_SELF, 1, size, nullptr, &block.y));
  COSIM_PETSC(KSPCreate(PETSC_COMM_SELF, &block.ksp));
  COSIM_PETSC(KSPSetOptionsPrefix(block.ksp, "ibm_forcing_sub_"));
  // Solved exactly: a body alone then converges in one iteration whatever its size, where
  // incomplete Cholesky (`-ibm_forcing_sub_pc_type icc`) took the limit of 50 for one
  // sphere of d/h 16, and 23 against 16 per step in a cloud of 1,000 spheres of d/h 6 at
  // three quarters of the cost (bench/particulate/README.md, bench/fluid_throughput/README.md).
  COSIM_PETSC(KSPSetType(block.ksp, KSPPREONLY));
  PC pc = nullptr;
  COSIM_PETSC(KSPGetPC(block.ksp, &pc));
  // A symmetric block by Cholesky, half the factor's memory and its triangular solves of
  // LU's; CHOLMOD's where PETSc has it, the fastest of the factors tried on Aguilar's bed
  // (bench/particulate/README.md).
  COSIM_PETSC(PCSetType(pc, symmetric ? PCCHOLESKY : PCLU));
  if (symmetric) COSIM_PETSC(MatSetOption(matrix, MAT_SYMMETRIC, PETSC_TRUE));
#ifdef PETSC_HAVE_SUITESPARSE
  if (symmetric) COSIM_PETSC(PCFactorSetMatSolverType(pc, MATSOLVERCHOLMOD));
#endif
  COSIM_PETSC(KSPSetOperators(block.ksp, matrix, matrix));
  COSIM_PETSC(KSPSetFromOptions(block.ksp));
  COSIM_PETSC(KSPSetUp(block.ksp));
  return block;
}

void BodyBlockSolvers::update(Mat B, std::span<const std::size_t> first_marker, bool symmetric) {
  PetscInt first = 0, end = 0;
  COSIM_PETSC(MatGetOwnershipRange(B, &first, &end));
  Mat local = nullptr;  // B's rows and columns on this rank, numbered from 0
  COSIM_PETSC(MatGetDiagonalBlock(B, &local));
  std::vector<Block> kept;
  auto next = blocks_.begin();
  for (std::size_t b = 0; b + 1 < first_marker.size(); ++b) {
    const auto lo = static_cast<PetscInt>(3 * first_marker[b]), hi = static_cast<PetscInt>(3 * first_marker[b + 1]);
    if (hi <= lo || lo < first || hi > end) continue;
    IS rows = nullptr;
    COSIM_PETSC(ISCreateStride(PETSC_COMM_SELF, hi - lo, lo - first, 1, &rows));
    Mat matrix = nullptr;
    COSIM_PETSC(MatCreateSubMatrix(local, rows, rows, MAT_INITIAL_MATRIX, &matrix));
    COSIM_PETSC(ISDestroy(&rows));
    // The last step's blocks come by ascending body, as the bodies do here.
    while (next != blocks_.end() && next->body < b) ++next;
    const auto old = next != blocks_.end() && next->body == b ? next : blocks_.end();
    // A factor chosen for the other kind of system (spread_at_theta's B is symmetric
    // while the bodies rest) is chosen again.
    if (old == blocks_.end() || old->symmetric != symmetric || !same_pattern(old->matrix, matrix)) {
      kept.push_back(factored(b, lo - first, matrix, symmetric));
      ++factorizations_;
      continue;
    }
    PetscBool same = PETSC_FALSE;
    COSIM_PETSC(MatEqual(old->matrix, matrix, &same));
    if (!same) {
      // New values where the old ones were: the solver sees the same pattern and keeps its
      // ordering and symbolic factors.
      COSIM_PETSC(MatCopy(matrix, old->matrix, SAME_NONZERO_PATTERN));
      COSIM_PETSC(KSPSetUp(old->ksp));
      ++refactorizations_;
    }
    COSIM_PETSC(MatDestroy(&matrix));
    kept.push_back(*old);
    kept.back().offset = lo - first;
    *old = Block{};
  }
  for (Block& block : blocks_) destroy(block);
  blocks_ = std::move(kept);
}

void BodyBlockSolvers::apply(Vec x, Vec y) const {
  COSIM_PETSC(VecCopy(x, y));
  const PetscScalar* in = nullptr;
  PetscScalar* out = nullptr;
  COSIM_PETSC(VecGetArrayRead(x, &in));
  COSIM_PETSC(VecGetArray(y, &out));
  for (const Block& block : blocks_) {
    COSIM_PETSC(VecPlaceArray(block.x, in + block.offset));
    COSIM_PETSC(VecPlaceArray(block.y, out + block.offset));
    COSIM_PETSC(KSPSolve(block.ksp, block.x, block.y));
    COSIM_PETSC(VecResetArray(block.x));
    COSIM_PETSC(VecResetArray(block.y));
  }
  COSIM_PETSC(VecRestoreArray(y, &out));
  COSIM_PETSC(VecRestoreArrayRead(x, &in));
}

}  // namespace cosim::fluid::ibm
