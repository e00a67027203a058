#pragma once
// The staggered (MAC) grid as PETSc DMDAs: pressure at cell centres on a scalar DMDA (so
// multigrid and KSPSetComputeOperators work on it as on any DMDA), and one scalar DMDA
// per velocity component holding that component on the cell faces normal to it. Face i of
// component c lies at the lower side of cell i along c; a bounded axis has one more face
// than cells. A fifth, ghosted DMDA holds other cell-centred fields. All share one
// partition, so a rank owns the faces of its cells (plus the last face of the domain on
// the last rank) and every stencil stays within one ghost layer.
#include <petscdmda.h>

#include <array>

#include "fluid/grid/axis.hpp"

namespace cosim::fluid::grid {

using Index = std::array<PetscInt, 3>;
using Point = std::array<double, 3>;

// Owned index range of a DMDA on this rank: lo inclusive, hi exclusive.
struct Box {
  Index lo{};
  Index hi{};
};

inline Index shifted(Index p, int axis, PetscInt by) {
  p[static_cast<std::size_t>(axis)] += by;
  return p;
}

template <typename F>
void for_each_index(const Box& b, F&& f) {
  for (PetscInt k = b.lo[2]; k < b.hi[2]; ++k)
    for (PetscInt j = b.lo[1]; j < b.hi[1]; ++j)
      for (PetscInt i = b.lo[0]; i < b.hi[0]; ++i) f(Index{i, j, k});
}

// Component index of a cell-centred quantity in position(), next to the velocity components 0..2.
inline constexpr int kCellCentre = -1;

using Axes = std::array<Axis, 3>;  // x, y, z

// The smallest width of the cell at x over the axes that carry variation (all but a
// two-dimensional grid's one periodic cell): how fine the grid is where a body sits.
double finest_width_at(const Axes& axes, const Point& x);

class Grid {
 public:
  // `ranks`: how many ranks share each axis (their product the communicator's size), or
  // PETSC_DECIDE along an axis for PETSc's choice (its default cut keeps the ranks' shared
  // faces few, which for a grid taller than wide is across its height).
  Grid(MPI_Comm comm, std::array<Axis, 3> axes,
       std::array<PetscInt, 3> ranks = {PETSC_DECIDE, PETSC_DECIDE, PETSC_DECIDE});
  ~Grid();
  Grid(const Grid&) = delete;
  Grid& operator=(const Grid&) = delete;

  MPI_Comm comm() const { return comm_; }
  const Axis& axis(int d) const { return axes_[static_cast<std::size_t>(d)]; }
  const Axes& axes() const { return axes_; }
  DM pressure_dm() const { return pressure_; }
  DM velocity_dm(int c) const { return velocity_[static_cast<std::size_t>(c)]; }
  // Cell-centred fields that stencils read with diagonal neighbours and boundary ghosts
  // (the viscosity; later the FBM indicator). Same partition as the pressure.
  DM cell_dm() const { return cells_; }
  Box owned(DM dm) const;
  Box ghosted(DM dm) const;  // owned plus the ghost layer
  std::array<PetscInt, 3> cells() const;

  // Where unknown p of component c (or kCellCentre) sits.
  Point position(int c, const Index& p) const;
  // True for a face of component c on a bounded domain face: its value comes from the
  // boundary condition, not from the momentum equation.
  bool on_boundary(int c, const Index& p) const;
  double cell_volume(const Index& cell) const;
  // The control volume of face p of component c, not a boundary face: from the centre of
  // the cell below to that of the cell above along c, the cell's widths across.
  double face_volume(int c, const Index& p) const;
  double finest_width_at(const Point& x) const { return fluid::grid::finest_width_at(axes_, x); }

 private:
  void create(const std::array<PetscInt, 3>& layout);  // ranks along each axis, as Grid() takes them
  void release();

  MPI_Comm comm_;
  std::array<Axis, 3> axes_;
  DM pressure_ = nullptr;
  std::array<DM, 3> velocity_{};
  DM cells_ = nullptr;
};

// Calls f(ghost, inside, axis, side) for every point of dm's ghost layer beyond a bounded
// face of an axis other than `along` (a component's own axis has real boundary unknowns;
// pass kCellCentre for cell-centred fields), inside being the point next to it in the domain.
template <typename F>
void for_each_boundary_ghost(const Grid& grid, DM dm, int along, F&& f) {
  Index lo, m;
  DMDAGetGhostCorners(dm, &lo[0], &lo[1], &lo[2], &m[0], &m[1], &m[2]);
  for (int d = 0; d < 3; ++d) {
    const Axis& axis = grid.axis(d);
    if (axis.periodic() || d == along) continue;
    for (const bool lower : {true, false}) {
      const PetscInt ghost = lower ? -1 : axis.cells();
      if (ghost < lo[d] || ghost >= lo[d] + m[d]) continue;
      Box layer{lo, {lo[0] + m[0], lo[1] + m[1], lo[2] + m[2]}};
      layer.lo[d] = ghost;
      layer.hi[d] = ghost + 1;
      for_each_index(layer, [&](const Index& g) {
        Index inside = g;
        inside[d] = lower ? 0 : axis.cells() - 1;
        f(g, inside, d, lower);
      });
    }
  }
}

}  // namespace cosim::fluid::grid
