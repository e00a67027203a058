#pragma once
// Hydrodynamic force and torque on one body by the fictitious-boundary volume integral
//   F_i = -int sigma_ij d_j(alpha_i) dV,   T = -int (x - x_c) x (sigma . grad alpha) dV,
//   sigma = -p I + mu (grad u + grad u^T),
// with alpha_i the body's indicator at the faces of velocity component i: 1 where the
// rigid velocity is imposed, 0 elsewhere. On the MAC grid d_i(alpha_i) lives at the cell
// centres and d_j(alpha_i) on the edges, exactly where sigma_ii and sigma_ij live, so no
// stress is interpolated; and by summation by parts the integral equals the sum over the
// imposed faces of the discrete momentum residual div(sigma)_i dV, i.e. the force the
// Dirichlet rows exert, with the pressures inside the body cancelling. Only cells and
// edges where alpha_i jumps (the body's surface) are visited.
#include <Eigen/Core>
#include <array>

#include "fluid/bodies/body_treatment.hpp"
#include "fluid/navier_stokes/navier_stokes.hpp"
#include "fluid/staircase/fbm_indicator.hpp"

namespace cosim::fluid::staircase {

// Collective: sums over all ranks. face_alpha[i] covers the ghosted faces of component i;
// a face counts as the body's where it is >= 1/2 (the imposition rule). The stress is that
// of the flow's current velocity and pressure, with the generalized-Newtonian viscosity
// of its last step.
bodies::HydrodynamicLoad hydrodynamic_load(const navier_stokes::NavierStokes& flow,
                                           const std::array<const bodies::IndicatorPatch*, 3>& face_alpha,
                                           const Eigen::Vector3d& centre);

}  // namespace cosim::fluid::staircase
