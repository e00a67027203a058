#include "fluid/window_response.hpp"

#include <cmath>
#include <numbers>

namespace cosim::fluid {

using bodies::BodyTreatment;
using bodies::HydrodynamicLoad;
using bodies::RigidBody;
using grid::Axis;
using grid::BoundaryConditions;
using grid::Grid;
using grid::Point;
using navier_stokes::FluidProperties;
using navier_stokes::NavierStokes;
using navier_stokes::StepReport;
using navier_stokes::TimeStepOptions;

namespace {

using Vector6d = Eigen::Matrix<double, 6, 1>;

// A periodic box of cells of width h around the origin, three mean half-extents beyond a
// body of these half-extents on every side, or one cell `layer` thick along a
// two-dimensional grid's flat axis. An even number of cells per axis, so a body near the
// origin sits off the grid's planes by the same fraction of a cell on every axis.
std::array<Axis, 3> box_around(const Eigen::Vector3d& half, double h, int flat, double layer) {
  const double mean = flat < 0 ? std::cbrt(half.prod()) : std::sqrt(half.prod() / half[flat]);
  const auto axis = [&](int d) {
    if (d == flat) return Axis::uniform(1, -0.5 * layer, 0.5 * layer, true);
    const int cells = 2 * static_cast<int>(std::ceil((half[d] + 3 * mean) / h));
    return Axis::uniform(cells, -0.5 * cells * h, 0.5 * cells * h, true);
  };
  return {axis(0), axis(1), axis(2)};
}

// The measurement's steps are logged apart from the flow's own: -log_view's stage
// "FluidResponse".
class LoggedApart {
 public:
  LoggedApart() {
    static const PetscLogStage stage = [] {
      PetscLogStage s = 0;
      COSIM_PETSC(PetscLogStageRegister("FluidResponse", &s));
      return s;
    }();
    COSIM_PETSC(PetscLogStagePush(stage));
  }
  ~LoggedApart() { PetscLogStagePop(); }
  LoggedApart(const LoggedApart&) = delete;
  LoggedApart& operator=(const LoggedApart&) = delete;
};

}  // namespace

WindowResponse window_response(const Grid& grid, const RigidBody& body, const FluidProperties& fluid,
                               const TimeStepOptions& steps, const BodyOptions& method, double window) {
  const LoggedApart logged;
  const geometry::Aabb extent =
      geometry::world_aabb(body.shape, geometry::Pose(Eigen::Vector3d::Zero(), Eigen::Quaterniond::Identity()));
  const Eigen::Vector3d& at = body.pose.position();
  const double h = grid.finest_width_at({at[0], at[1], at[2]});
  int flat = -1;
  for (int d = 0; d < 3; ++d)
    if (grid.axis(d).degenerate()) flat = d;
  Grid box(PETSC_COMM_SELF,
           box_around(0.5 * (extent.max - extent.min), h, flat, flat < 0 ? 0 : grid.axis(flat).width(0)));
  BoundaryConditions bc(box);
  Eigen::Vector3d centre = h * Eigen::Vector3d(0.137, 0.291, 0.413);
  if (flat >= 0) centre[flat] = 0;
  FluidProperties at_rest = fluid;
  at_rest.body_force = {};
  NavierStokes flow(box, bc, at_rest, steps);
  flow.set_velocity([](const Point&) { return Point{0, 0, 0}; });
  const std::unique_ptr<BodyTreatment> bodies = make_bodies(box, method);
  bodies->add({body.shape, geometry::Pose(centre, Eigen::Quaterniond::Identity())});
  const std::vector<double> rest = flow.state(), held = bodies->state();

  // The window-mean loads of kResponseWindows windows, the body's velocity changed by
  // `unit` from rest (ramped over the first window, held after it; its pose moved by the
  // integral).
  const auto loads = [&](const Vector6d& unit) {
    flow.restore(rest);
    bodies->restore(held);
    const auto place = [&](double s) {
      const double ramp = std::min(s, window) / window,
                   travelled = s <= window ? 0.5 * s * s / window : s - 0.5 * window;
      const Eigen::Vector3d turned = travelled * unit.tail<3>();
      const Eigen::Quaterniond q = turned.norm() > 0
                                       ? Eigen::Quaterniond(Eigen::AngleAxisd(turned.norm(), turned.normalized()))
                                       : Eigen::Quaterniond::Identity();
      bodies->move(0, geometry::Pose(centre + travelled * unit.head<3>(), q), ramp * unit.head<3>(),
                   ramp * unit.tail<3>());
    };
    std::vector<Vector6d> out(kResponseWindows, Vector6d::Zero());
    for (int k = 0; k < kResponseWindows; ++k)
      flow.advance_to((k + 1) * window, bodies->for_step(), place, [&](const StepReport& step) {
        const HydrodynamicLoad load = bodies->loads(flow)[0];
        out[static_cast<std::size_t>(k)].head<3>() += load.force * step.dt / window;
        out[static_cast<std::size_t>(k)].tail<3>() += load.torque * step.dt / window;
      });
    return out;
  };
  // A thousandth of a cell per window: small enough for the convection, quadratic in it,
  // to stay out of the response.
  const double change = 1e-3 * h / window;
  WindowResponse out;
  out.kernel.assign(kResponseWindows, WindowResponse::Matrix6d::Zero());
  for (int mode = 0; mode < 6; ++mode) {
    const std::vector<Vector6d> changed = loads(change * Vector6d::Unit(mode));
    for (int k = 0; k < kResponseWindows; ++k)
      out.kernel[static_cast<std::size_t>(k)].col(mode) = -changed[static_cast<std::size_t>(k)] / change;
  }
  const double mu = fluid.viscosity.newtonian() ? fluid.viscosity(0) : 0.0;
  const double r = std::cbrt(3 * geometry::volume(body.shape) / (4 * std::numbers::pi));
  out.added_damping.topLeftCorner<3, 3>().diagonal().setConstant(6 * std::numbers::pi * mu * r);
  out.added_damping.bottomRightCorner<3, 3>().diagonal().setConstant(8 * std::numbers::pi * mu * r * r * r);
  out.added_mass = window * (out.kernel[0] - 0.5 * out.added_damping);
  return out;
}

}  // namespace cosim::fluid
