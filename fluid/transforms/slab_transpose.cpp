#include "fluid/transforms/slab_transpose.hpp"

#include <algorithm>
#include <tuple>
#include <vector>

#include "fluid/petsc_check.hpp"

namespace cosim::fluid::transforms {

std::pair<PetscInt, PetscInt> share(PetscInt n, int rank, int size) {
  const PetscInt base = n / size, extra = n % size;
  const PetscInt begin = rank * base + std::min<PetscInt>(rank, extra);
  return {begin, begin + base + (rank < extra ? 1 : 0)};
}

SlabTranspose::SlabTranspose(DM dm) {
  COSIM_PETSC(PetscObjectGetComm(reinterpret_cast<PetscObject>(dm), &comm_));
  COSIM_PETSC(DMDAGetInfo(dm, nullptr, &n_[0], &n_[1], &n_[2], nullptr, nullptr, nullptr, nullptr, nullptr, nullptr,
                          nullptr, nullptr, nullptr));
  int rank = 0, size = 1;
  MPI_Comm_rank(comm_, &rank);
  MPI_Comm_size(comm_, &size);
  serial_ = size == 1;
  std::tie(k_begin_, k_end_) = share(n_[2], rank, size);
  std::tie(j_begin_, j_end_) = share(n_[1], rank, size);
  if (!serial_) create_or_release([&] { create_scatters(dm); }, [this] { release(); });
}

SlabTranspose::~SlabTranspose() { release(); }

void SlabTranspose::release() {
  VecScatterDestroy(&to_planes_);
  VecScatterDestroy(&to_lines_);
  VecDestroy(&planes_);
  VecDestroy(&lines_);
}

// planes_ holds whole x-y planes k_begin_ .. k_end_ in natural order (so its global index
// is the natural one); lines_ holds rows j_begin_ .. j_end_ as (j, k, i), whole z lines.
void SlabTranspose::create_scatters(DM dm) {
  const PetscInt nx = n_[0], ny = n_[1], nz = n_[2];
  const PetscInt plane = nx * ny;
  const PetscInt in_planes = plane * (k_end_ - k_begin_), in_lines = nx * nz * (j_end_ - j_begin_);
  COSIM_PETSC(VecCreateMPI(comm_, in_planes, PETSC_DETERMINE, &planes_));
  COSIM_PETSC(VecCreateMPI(comm_, in_lines, PETSC_DETERMINE, &lines_));

  std::vector<PetscInt> from(static_cast<std::size_t>(in_planes));
  for (PetscInt n = 0; n < in_planes; ++n) from[static_cast<std::size_t>(n)] = plane * k_begin_ + n;
  AO ao;
  COSIM_PETSC(DMDAGetAO(dm, &ao));
  COSIM_PETSC(AOApplicationToPetsc(ao, in_planes, from.data()));
  IS is_from, is_to;
  COSIM_PETSC(ISCreateGeneral(comm_, in_planes, from.data(), PETSC_COPY_VALUES, &is_from));
  COSIM_PETSC(ISCreateStride(comm_, in_planes, plane * k_begin_, 1, &is_to));
  Vec global;
  COSIM_PETSC(DMGetGlobalVector(dm, &global));
  const PetscErrorCode made = VecScatterCreate(global, is_from, planes_, is_to, &to_planes_);
  COSIM_PETSC(DMRestoreGlobalVector(dm, &global));
  ISDestroy(&is_from);
  ISDestroy(&is_to);
  COSIM_PETSC(made);

  from.resize(static_cast<std::size_t>(in_lines));
  std::size_t at = 0;
  for (PetscInt j = j_begin_; j < j_end_; ++j)
    for (PetscInt k = 0; k < nz; ++k)
      for (PetscInt i = 0; i < nx; ++i) from[at++] = (k * ny + j) * nx + i;
  COSIM_PETSC(ISCreateGeneral(comm_, in_lines, from.data(), PETSC_COPY_VALUES, &is_from));
  COSIM_PETSC(ISCreateStride(comm_, in_lines, nx * nz * j_begin_, 1, &is_to));
  const PetscErrorCode made_lines = VecScatterCreate(planes_, is_from, lines_, is_to, &to_lines_);
  ISDestroy(&is_from);
  ISDestroy(&is_to);
  COSIM_PETSC(made_lines);
}

void SlabTranspose::run(Vec in, Vec out, const OnPlanes& forward, const OnLines& lines, const OnPlanes& backward) {
  const PetscInt nx = n_[0], ny = n_[1], nz = n_[2];
  if (serial_) {
    // One rank holds everything in natural order: all passes in place in out.
    COSIM_PETSC(VecCopy(in, out));
    PetscScalar* data = nullptr;
    COSIM_PETSC(VecGetArray(out, &data));
    forward(data, 0, nz);
    lines(data, 0, ny, nx, nx * ny);
    backward(data, 0, nz);
    COSIM_PETSC(VecRestoreArray(out, &data));
    return;
  }
  COSIM_PETSC(VecScatterBegin(to_planes_, in, planes_, INSERT_VALUES, SCATTER_FORWARD));
  COSIM_PETSC(VecScatterEnd(to_planes_, in, planes_, INSERT_VALUES, SCATTER_FORWARD));
  PetscScalar* data = nullptr;
  COSIM_PETSC(VecGetArray(planes_, &data));
  forward(data, k_begin_, k_end_);
  COSIM_PETSC(VecRestoreArray(planes_, &data));
  COSIM_PETSC(VecScatterBegin(to_lines_, planes_, lines_, INSERT_VALUES, SCATTER_FORWARD));
  COSIM_PETSC(VecScatterEnd(to_lines_, planes_, lines_, INSERT_VALUES, SCATTER_FORWARD));
  COSIM_PETSC(VecGetArray(lines_, &data));
  lines(data, j_begin_, j_end_, nz * nx, nx);
  COSIM_PETSC(VecRestoreArray(lines_, &data));
  COSIM_PETSC(VecScatterBegin(to_lines_, lines_, planes_, INSERT_VALUES, SCATTER_REVERSE));
  COSIM_PETSC(VecScatterEnd(to_lines_, lines_, planes_, INSERT_VALUES, SCATTER_REVERSE));
  COSIM_PETSC(VecGetArray(planes_, &data));
  backward(data, k_begin_, k_end_);
  COSIM_PETSC(VecRestoreArray(planes_, &data));
  COSIM_PETSC(VecScatterBegin(to_planes_, planes_, out, INSERT_VALUES, SCATTER_REVERSE));
  COSIM_PETSC(VecScatterEnd(to_planes_, planes_, out, INSERT_VALUES, SCATTER_REVERSE));
}

}  // namespace cosim::fluid::transforms
