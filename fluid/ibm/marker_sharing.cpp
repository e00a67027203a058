#include "fluid/ibm/marker_sharing.hpp"

#include <algorithm>
#include <cmath>

#include "fluid/petsc_check.hpp"

namespace cosim::fluid::ibm {

MarkerSharing::MarkerSharing(MPI_Comm comm, std::span<const PetscInt> ids, PetscInt roots)
    : comm_(comm), roots_(roots) {
  PetscLayout layout = nullptr;
  COSIM_PETSC(PetscLayoutCreateFromSizes(comm, roots, PETSC_DECIDE, 1, &layout));
  COSIM_PETSC(PetscLayoutGetRange(layout, &first_root_, nullptr));
  COSIM_PETSC(PetscSFCreate(comm, &sf_));
  COSIM_PETSC(
      PetscSFSetGraphLayout(sf_, layout, static_cast<PetscInt>(ids.size()), nullptr, PETSC_COPY_VALUES, ids.data()));
  COSIM_PETSC(PetscLayoutDestroy(&layout));
  COSIM_PETSC(PetscSFSetUp(sf_));
  once_.assign(ids.size(), 1.0);
  sum(once_);
  double local = 0;
  for (double& holders : once_) {
    holders = 1 / holders;
    local += holders;
  }
  MPI_Allreduce(&local, &count_, 1, MPI_DOUBLE, MPI_SUM, comm_);
  count_ = std::round(count_);
}

MarkerSharing::~MarkerSharing() { PetscSFDestroy(&sf_); }

void MarkerSharing::sum(std::vector<double>& values) const {
  roots_buffer_.assign(static_cast<std::size_t>(roots_), 0.0);
  COSIM_PETSC(PetscSFReduceBegin(sf_, MPI_DOUBLE, values.data(), roots_buffer_.data(), MPI_SUM));
  COSIM_PETSC(PetscSFReduceEnd(sf_, MPI_DOUBLE, values.data(), roots_buffer_.data(), MPI_SUM));
  from_roots(roots_buffer_.data(), values);
}

std::array<double, 3> MarkerSharing::dot(const std::vector<double>& a, const std::vector<double>& b) const {
  std::array<double, 3> out{};
  for (std::size_t i = 0; i < a.size(); ++i) out[i % 3] += once_[i] * a[i] * b[i];
  MPI_Allreduce(MPI_IN_PLACE, out.data(), 3, MPI_DOUBLE, MPI_SUM, comm_);
  return out;
}

double MarkerSharing::largest(const std::vector<double>& a) const {
  double m = 0;
  for (double v : a) m = std::max(m, std::abs(v));
  return largest(m);
}

double MarkerSharing::largest(double local) const {
  MPI_Allreduce(MPI_IN_PLACE, &local, 1, MPI_DOUBLE, MPI_MAX, comm_);
  return local;
}

void MarkerSharing::to_roots(const std::vector<double>& leaves, PetscScalar* roots) const {
  std::fill_n(roots, roots_, 0.0);
  COSIM_PETSC(PetscSFReduceBegin(sf_, MPI_DOUBLE, leaves.data(), roots, MPI_REPLACE));
  COSIM_PETSC(PetscSFReduceEnd(sf_, MPI_DOUBLE, leaves.data(), roots, MPI_REPLACE));
}

void MarkerSharing::from_roots(const PetscScalar* roots, std::vector<double>& leaves) const {
  COSIM_PETSC(PetscSFBcastBegin(sf_, MPI_DOUBLE, roots, leaves.data(), MPI_REPLACE));
  COSIM_PETSC(PetscSFBcastEnd(sf_, MPI_DOUBLE, roots, leaves.data(), MPI_REPLACE));
}

void MarkerSharing::to_roots(const std::vector<double>& leaves, Vec roots) const {
  PetscScalar* a = nullptr;
  COSIM_PETSC(VecGetArray(roots, &a));
  to_roots(leaves, a);
  COSIM_PETSC(VecRestoreArray(roots, &a));
}

void MarkerSharing::from_roots(Vec roots, std::vector<double>& leaves) const {
  const PetscScalar* a = nullptr;
  COSIM_PETSC(VecGetArrayRead(roots, &a));
  from_roots(a, leaves);
  COSIM_PETSC(VecRestoreArrayRead(roots, &a));
}

}  // namespace cosim::fluid::ibm
