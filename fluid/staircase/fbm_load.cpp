#include "fluid/staircase/fbm_load.hpp"

#include <algorithm>

#include "fluid/petsc_check.hpp"

namespace cosim::fluid::staircase {

using bodies::HydrodynamicLoad;
using bodies::IndicatorPatch;
using grid::Axis;
using grid::Box;
using grid::for_each_index;
using grid::Grid;
using grid::Index;
using grid::kCellCentre;
using grid::LocalVelocity;
using grid::Point;
using grid::shifted;
using navier_stokes::NavierStokes;
using viscous::ViscosityField;

namespace {

Box intersection(Box a, const Box& b) {
  for (int d = 0; d < 3; ++d) {
    a.lo[d] = std::max(a.lo[d], b.lo[d]);
    a.hi[d] = std::min(a.hi[d], b.hi[d]);
  }
  return a;
}

Eigen::Vector3d vector(const Point& x) { return {x[0], x[1], x[2]}; }

class Integrator {
 public:
  Integrator(const NavierStokes& flow, const PetscScalar* const* const* p, const Eigen::Vector3d& centre)
      : grid_(flow.grid()),
        u_(flow.local_velocity()),
        nu_(flow.viscosity()),
        density_(flow.fluid().density),
        p_(p),
        centre_(centre) {}

  // -sigma_ii d_i(alpha_i) over the owned cells next to the body's i-faces.
  void normal(int i, const IndicatorPatch& alpha) {
    const Axis& a = grid_.axis(i);
    Box near = alpha.range();
    near.lo[i] -= 1;  // the cell below the lowest face
    for_each_index(intersection(near, grid_.owned(grid_.cell_dm())), [&](const Index& m) {
      const double jump = imposed(i, alpha, shifted(m, i, 1)) - imposed(i, alpha, m);
      if (jump == 0) return;
      const double width = a.width(static_cast<int>(m[i]));
      const double strain = (u_(i, shifted(m, i, 1)) - u_(i, m)) / width;
      const double sigma = -p_[m[2]][m[1]][m[0]] + 2 * density_ * nu_.at_cell(m) * strain;
      add(i, -sigma * jump * grid_.cell_volume(m) / width, grid_.position(kCellCentre, m));
    });
  }

  // -sigma_ij d_j(alpha_i) on the edges between i-faces q - e_j and q, for the edges whose
  // face q this rank owns.
  void shear(int i, int j, const IndicatorPatch& alpha) {
    const Axis& ai = grid_.axis(i);
    const Axis& aj = grid_.axis(j);
    const Axis& ak = grid_.axis(3 - i - j);
    Box near = alpha.range();
    near.hi[j] += 1;  // the edge above the highest face
    for_each_index(intersection(near, grid_.owned(grid_.velocity_dm(i))), [&](const Index& q) {
      // A body reaching a wall gets no traction from the wall side.
      if (!aj.periodic() && q[j] == 0) return;
      const double jump = imposed(i, alpha, q) - imposed(i, alpha, shifted(q, j, -1));
      if (jump == 0) return;
      const int qi = static_cast<int>(q[i]), qj = static_cast<int>(q[j]);
      const double dui_dxj = (u_(i, q) - u_(i, shifted(q, j, -1))) / (aj.centre(qj) - aj.centre(qj - 1));
      const double duj_dxi = (u_(j, q) - u_(j, shifted(q, i, -1))) / (ai.centre(qi) - ai.centre(qi - 1));
      const double sigma = density_ * nu_.at_edge(i, j, q, q[j]) * (dui_dxj + duj_dxi);
      // Area of the edge's control volume normal to j.
      const double area = (ai.centre(qi) - ai.centre(qi - 1)) * ak.width(static_cast<int>(q[3 - i - j]));
      Point x = grid_.position(i, q);
      x[static_cast<std::size_t>(j)] = aj.face(qj);
      add(i, -sigma * jump * area, x);
    });
  }

  double* totals() { return load_; }

 private:
  double imposed(int i, const IndicatorPatch& alpha, const Index& p) const {
    return alpha(p) >= 0.5 && !grid_.on_boundary(i, p) ? 1.0 : 0.0;
  }

  void add(int i, double f, const Point& x) {
    Eigen::Vector3d force = Eigen::Vector3d::Zero();
    force[i] = f;
    const Eigen::Vector3d moment = (vector(x) - centre_).cross(force);
    load_[i] += f;
    for (int d = 0; d < 3; ++d) load_[3 + d] += moment[d];
  }

  const Grid& grid_;
  const LocalVelocity& u_;
  const ViscosityField& nu_;
  double density_;
  const PetscScalar* const* const* p_;
  Eigen::Vector3d centre_;
  double load_[6] = {};  // force, torque
};

}  // namespace

HydrodynamicLoad hydrodynamic_load(const NavierStokes& flow, const std::array<const IndicatorPatch*, 3>& face_alpha,
                                   const Eigen::Vector3d& centre) {
  const Grid& grid = flow.grid();
  DM pdm = grid.pressure_dm();
  Vec p_local;
  COSIM_PETSC(DMGetLocalVector(pdm, &p_local));
  COSIM_PETSC(DMGlobalToLocalBegin(pdm, flow.pressure(), INSERT_VALUES, p_local));
  COSIM_PETSC(DMGlobalToLocalEnd(pdm, flow.pressure(), INSERT_VALUES, p_local));
  const PetscScalar*** p = nullptr;
  COSIM_PETSC(DMDAVecGetArrayRead(pdm, p_local, &p));
  Integrator integral(flow, p, centre);
  for (int i = 0; i < 3; ++i) {
    const IndicatorPatch& alpha = *face_alpha[static_cast<std::size_t>(i)];
    // Along a one-cell periodic axis nothing varies: no jumps there.
    if (!grid.axis(i).degenerate()) integral.normal(i, alpha);
    for (int j = 0; j < 3; ++j)
      if (j != i && !grid.axis(j).degenerate()) integral.shear(i, j, alpha);
  }
  COSIM_PETSC(DMDAVecRestoreArrayRead(pdm, p_local, &p));
  COSIM_PETSC(DMRestoreLocalVector(pdm, &p_local));
  double* load = integral.totals();
  MPI_Allreduce(MPI_IN_PLACE, load, 6, MPI_DOUBLE, MPI_SUM, grid.comm());
  return {Eigen::Vector3d(load[0], load[1], load[2]), Eigen::Vector3d(load[3], load[4], load[5])};
}

}  // namespace cosim::fluid::staircase
