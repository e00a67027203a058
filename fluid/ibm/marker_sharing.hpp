#pragma once
// The markers a rank takes part in are those whose kernels touch its faces, so its work and
// memory grow with the bodies near it, not with all of them. A marker whose kernel spans
// several ranks is held by each (a leaf of a PETSc star forest) and its interpolated
// velocity is the sum of their parts, joined through one root per value: the values'
// global numbers laid out over the ranks in ranges the caller chooses (whole bodies each,
// about evenly: forcing_system.hpp), so the messages, too, go with a rank's own markers. Every holder then holds the
// same values and runs the same arithmetic on them; sums over the markers count each once.
#include <petscsf.h>
#include <petscvec.h>

#include <array>
#include <span>
#include <vector>

namespace cosim::fluid::ibm {

class MarkerSharing {
 public:
  // `ids`: the global number of each value this rank holds; `roots`: how many values' roots
  // this rank keeps, the next range of global numbers after the lower ranks' (collective).
  MarkerSharing(MPI_Comm comm, std::span<const PetscInt> ids, PetscInt roots);
  ~MarkerSharing();
  MarkerSharing(const MarkerSharing&) = delete;
  MarkerSharing& operator=(const MarkerSharing&) = delete;

  // values[i] = the sum of value i over the ranks that hold it (collective).
  void sum(std::vector<double>& values) const;
  // sum_i a_i b_i over every value held anywhere, once each, per component (i % 3; collective).
  std::array<double, 3> dot(const std::vector<double>& a, const std::vector<double>& b) const;
  // The largest |a_i| over every rank (collective).
  double largest(const std::vector<double>& a) const;
  // The largest `local` over every rank (collective).
  double largest(double local) const;
  // The values held anywhere (collective at construction).
  double count() const { return count_; }
  // The share of value i this rank counts in a sum over the markers: 1 / its holders.
  double once(std::size_t i) const { return once_[i]; }

  // This rank's roots, the values a parallel Krylov solve over the markers owns here, and
  // the global number of the first.
  PetscInt roots() const { return roots_; }
  PetscInt first_root() const { return first_root_; }
  MPI_Comm comm() const { return comm_; }
  // A parallel vector of this rank's roots from the values held (any holder's), and back.
  void to_roots(const std::vector<double>& leaves, Vec roots) const;
  void from_roots(Vec roots, std::vector<double>& leaves) const;

 private:
  void to_roots(const std::vector<double>& leaves, PetscScalar* roots) const;
  void from_roots(const PetscScalar* roots, std::vector<double>& leaves) const;

  MPI_Comm comm_;
  PetscSF sf_ = nullptr;
  PetscInt roots_ = 0, first_root_ = 0;
  std::vector<double> once_;
  mutable std::vector<double> roots_buffer_;  // sum()'s, kept: it runs several times a step
  double count_ = 0;
};

}  // namespace cosim::fluid::ibm
