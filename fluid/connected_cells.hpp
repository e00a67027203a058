#pragma once
// The pressure cells a projection can correct: those joined through open faces (neither
// imposed by a body nor a wall) to the bulk fluid. Cells inside bodies, and pockets that
// bodies close against each other or against a wall (spheres landing on a floor, touching
// beads), are not: each pocket would be a singular block of the pressure operator, its
// level undetermined and its right-hand side inconsistent, and the solve would diverge.
// Their correction is fixed at zero instead.
#include <cstdint>
#include <vector>

#include "fluid/boundary_conditions.hpp"
#include "fluid/grid.hpp"
#include "fluid/imposed_faces.hpp"

namespace cosim::fluid {

class ConnectedCells {
 public:
  // Collective. Seeds: cells on an outflow face, or without an outflow the cells with no
  // face imposed, the bulk being the largest region they reach (a pocket closed around an
  // untouched cell is not); regions are found by sweeps over open faces, exchanging ghosts
  // until nothing changes.
  void update(const Grid& grid, const BoundaryConditions& bc, const ImposedFaces& imposed);
  bool connected(const Index& cell) const;  // an owned cell

 private:
  Box owned_{};
  std::vector<std::uint8_t> reached_;
};

}  // namespace cosim::fluid
