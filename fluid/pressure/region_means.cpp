#include "fluid/pressure/region_means.hpp"

#include <algorithm>
#include <exception>
#include <numeric>

#include "fluid/petsc_check.hpp"

namespace cosim::fluid::pressure {

using grid::for_each_index;
using grid::Grid;
using grid::Index;

void RegionMeans::update(const Grid& grid, const ConnectedCells& connected) {
  comm_ = grid.comm();
  std::vector<double> labels;
  for (const double r : connected.regions())
    if (r != ConnectedCells::kOutflowRegion) labels.push_back(r);  // ascending, as regions() is
  runs_.clear();
  cells_.assign(labels.size(), 0.0);
  std::size_t i = 0;
  for_each_index(grid.owned(grid.pressure_dm()), [&](const Index& m) {
    const auto at = std::lower_bound(labels.begin(), labels.end(), connected.region(m));
    if (at != labels.end() && *at == connected.region(m)) {
      const auto r = static_cast<std::size_t>(at - labels.begin());
      if (!runs_.empty() && runs_.back().end == i && runs_.back().region == r)
        ++runs_.back().end;
      else
        runs_.push_back({i, i + 1, r});
      cells_[r] += 1;
    }
    ++i;
  });
  if (!cells_.empty())
    MPI_Allreduce(MPI_IN_PLACE, cells_.data(), static_cast<int>(cells_.size()), MPI_DOUBLE, MPI_SUM, comm_);
}

void RegionMeans::remove(Vec x) const {
  PetscScalar* v = nullptr;
  COSIM_PETSC(VecGetArray(x, &v));
  std::vector<double> mean(cells_.size(), 0.0);
  for (const Run& run : runs_) mean[run.region] += std::accumulate(v + run.begin, v + run.end, 0.0);
  MPI_Allreduce(MPI_IN_PLACE, mean.data(), static_cast<int>(mean.size()), MPI_DOUBLE, MPI_SUM, comm_);
  for (std::size_t r = 0; r < mean.size(); ++r) mean[r] /= cells_[r];
  for (const Run& run : runs_) {
    const double m = mean[run.region];  // a local: v might alias mean for all the compiler knows
    for (std::size_t k = run.begin; k < run.end; ++k) v[k] -= m;
  }
  COSIM_PETSC(VecRestoreArray(x, &v));
}

namespace {
// Called from inside PETSc: an exception must not cross its C frames.
PetscErrorCode remove_means(MatNullSpace, Vec x, void* means) {
  try {
    static_cast<const RegionMeans*>(means)->remove(x);
  } catch (const std::exception&) {
    return PETSC_ERR_LIB;
  }
  return 0;
}
}  // namespace

MatNullSpace RegionMeans::null_space(MPI_Comm comm) const {
  MatNullSpace space = nullptr;
  COSIM_PETSC(MatNullSpaceCreate(comm, PETSC_FALSE, 0, nullptr, &space));
  COSIM_PETSC(MatNullSpaceSetFunction(space, remove_means, const_cast<RegionMeans*>(this)));
  return space;
}

}  // namespace cosim::fluid::pressure
