#pragma once
// Kinematic viscosity nu = mu(gamma)/rho at cell centres, and where the viscous fluxes need
// it: cell centres (normal stresses) and cell edges (shear stresses). A Newtonian fluid
// keeps one constant and stores no field.
#include <petscdmda.h>

#include "fluid/grid/grid.hpp"
#include "fluid/grid/local_velocity.hpp"
#include "fluid/viscous/viscosity_model.hpp"

namespace cosim::fluid::viscous {

class ViscosityField {
 public:
  ViscosityField(const grid::Grid& grid, ViscosityModel model, double density);
  ~ViscosityField();
  ViscosityField(const ViscosityField&) = delete;
  ViscosityField& operator=(const ViscosityField&) = delete;

  bool uniform() const { return model_.newtonian(); }
  // Re-evaluates the viscosity from the shear rate of u (nothing to do when uniform).
  void update(const grid::LocalVelocity& u);
  double at_cell(const grid::Index& cell) const;
  // On the edge where face p of component c meets face j of axis d (d != c).
  double at_edge(int c, int d, const grid::Index& p, PetscInt j) const;

 private:
  const grid::Grid& grid_;
  ViscosityModel model_;
  double density_;
  double constant_;  // the Newtonian nu
  Vec global_ = nullptr, local_ = nullptr;
  const PetscScalar*** array_ = nullptr;
};

// gamma = sqrt(2 D:D) at a cell centre: normal strain rates from the faces, shear rates
// averaged from the four edges around the cell in each plane.
double shear_rate(const grid::Grid& grid, const grid::LocalVelocity& u, const grid::Index& cell);

}  // namespace cosim::fluid::viscous
