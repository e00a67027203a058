#include "fluid/grid/grid.hpp"

#include <algorithm>
#include <limits>
#include <vector>

#include "fluid/petsc_check.hpp"

namespace cosim::fluid::grid {

namespace {
DMBoundaryType boundary_type(const Axis& a) { return a.periodic() ? DM_BOUNDARY_PERIODIC : DM_BOUNDARY_GHOSTED; }

using CornersFunction = PetscErrorCode (*)(DM, PetscInt*, PetscInt*, PetscInt*, PetscInt*, PetscInt*, PetscInt*);

Box corners(DM dm, CornersFunction get) {
  Box b;
  PetscInt m[3];
  COSIM_PETSC(get(dm, &b.lo[0], &b.lo[1], &b.lo[2], &m[0], &m[1], &m[2]));
  for (int d = 0; d < 3; ++d) b.hi[d] = b.lo[d] + m[d];
  return b;
}
}  // namespace

Grid::Grid(MPI_Comm comm, std::array<Axis, 3> axes, std::array<PetscInt, 3> ranks)
    : comm_(comm), axes_(std::move(axes)) {
  // Too many ranks for the cells fails here.
  create_or_release([this, &ranks] { create(ranks); }, [this] { release(); });
}

void Grid::create(const std::array<PetscInt, 3>& layout) {
  MPI_Comm comm = comm_;
  const auto n = cells();
  // Pressure needs no ghost points outside the domain (boundary fluxes are closed in the
  // operator), which keeps it a plain DMDA for the multigrid hierarchy.
  COSIM_PETSC(DMDACreate3d(comm, axes_[0].periodic() ? DM_BOUNDARY_PERIODIC : DM_BOUNDARY_NONE,
                           axes_[1].periodic() ? DM_BOUNDARY_PERIODIC : DM_BOUNDARY_NONE,
                           axes_[2].periodic() ? DM_BOUNDARY_PERIODIC : DM_BOUNDARY_NONE, DMDA_STENCIL_STAR, n[0], n[1],
                           n[2], layout[0], layout[1], layout[2], 1, 1, nullptr, nullptr, nullptr, &pressure_));
  COSIM_PETSC(DMSetOptionsPrefix(pressure_, "pressure_"));
  // Cell-centred values: a multigrid hierarchy halves the cell count and interpolates
  // piecewise constant (PETSc's DMDA cannot coarsen a one-cell axis, so geometric
  // multigrid needs every axis to have 2^(levels-1) * k cells).
  COSIM_PETSC(DMDASetInterpolationType(pressure_, DMDA_Q0));
  COSIM_PETSC(DMSetUp(pressure_));

  PetscInt ranks[3];
  COSIM_PETSC(DMDAGetInfo(pressure_, nullptr, nullptr, nullptr, nullptr, &ranks[0], &ranks[1], &ranks[2], nullptr,
                          nullptr, nullptr, nullptr, nullptr, nullptr));
  const PetscInt* ranges[3];
  COSIM_PETSC(DMDAGetOwnershipRanges(pressure_, &ranges[0], &ranges[1], &ranges[2]));

  for (int c = kCellCentre; c < 3; ++c) {
    std::array<std::vector<PetscInt>, 3> own;
    std::array<PetscInt, 3> size = n;
    for (int d = 0; d < 3; ++d) own[d].assign(ranges[d], ranges[d] + ranks[d]);
    if (c != kCellCentre && !axes_[c].periodic()) {
      own[c].back() += 1;  // the last rank along c also owns the closing boundary face
      size[c] += 1;
    }
    // Box stencil: convection and interpolation reach diagonal neighbours (i-1, j+1).
    DM& dm = c == kCellCentre ? cells_ : velocity_[c];
    COSIM_PETSC(DMDACreate3d(comm, boundary_type(axes_[0]), boundary_type(axes_[1]), boundary_type(axes_[2]),
                             DMDA_STENCIL_BOX, size[0], size[1], size[2], ranks[0], ranks[1], ranks[2], 1, 1,
                             own[0].data(), own[1].data(), own[2].data(), &dm));
    COSIM_PETSC(DMSetUp(dm));
  }
}

Grid::~Grid() { release(); }

void Grid::release() {
  for (auto& dm : velocity_) DMDestroy(&dm);
  DMDestroy(&cells_);
  DMDestroy(&pressure_);
}

std::array<PetscInt, 3> Grid::cells() const { return {axes_[0].cells(), axes_[1].cells(), axes_[2].cells()}; }

Box Grid::owned(DM dm) const { return corners(dm, DMDAGetCorners); }

Box Grid::ghosted(DM dm) const { return corners(dm, DMDAGetGhostCorners); }

Point Grid::position(int c, const Index& p) const {
  Point x;
  for (int d = 0; d < 3; ++d) {
    const auto i = static_cast<int>(p[d]);
    x[d] = d == c ? axes_[d].face(i) : axes_[d].centre(i);
  }
  return x;
}

bool Grid::on_boundary(int c, const Index& p) const {
  const Axis& a = axes_[c];
  return !a.periodic() && (p[c] == 0 || p[c] == a.cells());
}

double Grid::cell_volume(const Index& cell) const {
  return axes_[0].width(static_cast<int>(cell[0])) * axes_[1].width(static_cast<int>(cell[1])) *
         axes_[2].width(static_cast<int>(cell[2]));
}

double Grid::face_volume(int c, const Index& p) const {
  double v = 1;
  for (int d = 0; d < 3; ++d) {
    const auto i = static_cast<int>(p[d]);
    v *= d == c ? axes_[d].centre(i) - axes_[d].centre(i - 1) : axes_[d].width(i);
  }
  return v;
}

double finest_width_at(const Axes& axes, const Point& x) {
  double h = std::numeric_limits<double>::infinity();
  for (const std::size_t d : {0u, 1u, 2u})
    if (!axes[d].degenerate()) h = std::min(h, axes[d].width(axes[d].cell_at(x[d])));
  return h;
}

}  // namespace cosim::fluid::grid
