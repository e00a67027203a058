#pragma once
// The redistribution the transform solvers need: whole x-y planes on each rank for the
// transforms along x and y, then whole z lines for the tridiagonal solves along z, and
// back (PETSc scatters); the grid's own partition is left as it is. On one rank the data
// stays in place in natural order.
#include <petscdmda.h>

#include <functional>
#include <utility>

namespace cosim::fluid::transforms {

// [begin, end) of n items split over `size` ranks as evenly as possible.
std::pair<PetscInt, PetscInt> share(PetscInt n, int rank, int size);

class SlabTranspose {
 public:
  // dm: a scalar DMDA whose natural order is i fastest, then j, then k.
  explicit SlabTranspose(DM dm);
  ~SlabTranspose();
  SlabTranspose(const SlabTranspose&) = delete;
  SlabTranspose& operator=(const SlabTranspose&) = delete;

  // Whole planes k_begin .. k_end, each nx * ny in natural order.
  using OnPlanes = std::function<void(double* planes, PetscInt k_begin, PetscInt k_end)>;
  // Whole z lines of rows j_begin .. j_end: element (i, j, k) at
  // data[(j - j_begin) j_stride + k k_stride + i].
  using OnLines =
      std::function<void(double* data, PetscInt j_begin, PetscInt j_end, PetscInt j_stride, PetscInt k_stride)>;

  // out = backward(lines(forward(in))); in and out are global vectors of the DMDA.
  void run(Vec in, Vec out, const OnPlanes& forward, const OnLines& lines, const OnPlanes& backward);

  PetscInt nx() const { return n_[0]; }
  PetscInt ny() const { return n_[1]; }
  PetscInt nz() const { return n_[2]; }
  PetscInt k_begin() const { return k_begin_; }
  PetscInt k_end() const { return k_end_; }

 private:
  void create_scatters(DM dm);
  void release();

  MPI_Comm comm_;
  PetscInt n_[3] = {0, 0, 0};
  bool serial_ = true;
  PetscInt k_begin_ = 0, k_end_ = 0;        // this rank's x-y planes
  PetscInt j_begin_ = 0, j_end_ = 0;        // this rank's z lines: all i, j in range
  Vec planes_ = nullptr, lines_ = nullptr;  // several ranks only
  VecScatter to_planes_ = nullptr, to_lines_ = nullptr;
};

}  // namespace cosim::fluid::transforms
