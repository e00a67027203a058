#include "bench/fluid_accuracy/cases.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "bench/fluid_accuracy/channel.hpp"

namespace cosim::bench {
namespace {

using namespace cosim::fluid;
using fluid::bodies::BodyTreatment;
using fluid::bodies::StepBodies;
using fluid::grid::Axis;
using fluid::grid::Boundary;
using fluid::grid::BoundaryConditions;
using fluid::grid::Grid;
using fluid::grid::Point;
using fluid::grid::Side;
using fluid::ibm::ImmersedBoundary;
using fluid::navier_stokes::NavierStokes;
using fluid::navier_stokes::StageSeconds;
using fluid::navier_stokes::StepReport;
using fluid::navier_stokes::TimeStepOptions;
using fluid::staircase::FictitiousBoundary;
using fluid::viscous::ViscosityModel;

// Cylinder at (0.2, 0.2) in the channel, U_max 0.3, nu 1e-3. Along x: cells of h to
// x = 0.6, then 6 % wider each.
namespace dfg {
using namespace channel;
constexpr double Umax = 0.3, Umean = 2 * Umax / 3;
constexpr double kDrag = 5.5795;

Axis along_channel(double h) {
  std::vector<double> x;
  double width = h;
  for (double at = 0; at < L; at += width) {
    x.push_back(at);
    if (at > 0.6 - 1e-12) width *= 1.06;
  }
  x.push_back(L);
  if (L - x[x.size() - 2] < 0.5 * width) x.erase(x.end() - 2);  // no sliver at the outflow
  return Axis::from_faces(x, false);
}

Point parabola(const Point& x) { return Point{4 * Umax * x[1] * (H - x[1]) / (H * H), 0, 0}; }
}  // namespace dfg

// Advances `flow` with `bodies` by `interval` at a time (at most to t_max) until measure()
// moves by less than `tolerance` of itself over one interval; the steps taken.
template <typename Measure>
int run_to_steady(NavierStokes& flow, const StepBodies& bodies, double interval, double t_max, double tolerance,
                  Measure measure) {
  int steps = 0;
  double value = 0;
  for (double t = interval; t <= t_max; t += interval) {
    steps += static_cast<int>(flow.advance_to(t, bodies).size());
    const double before = value;
    value = measure();
    if (std::abs(value - before) < tolerance * std::abs(value)) break;
  }
  return steps;
}

double mean_u(const NavierStokes& flow, double cells) {
  // The mean over the cells of the face velocities: periodic, so one face per cell.
  PetscScalar total = 0;
  VecSum(flow.velocity(0), &total);
  return total / cells;
}

}  // namespace

FluidRun dfg_cylinder(int cells_per_diameter, const BodyOptions& method, const Eigen::Vector2d& shift) {
  using namespace dfg;
  const double start = MPI_Wtime();
  const Axis y = across(cells_per_diameter);
  const double h = H / y.cells();
  Grid grid(PETSC_COMM_WORLD, {along_channel(h), y, layer()});
  BoundaryConditions bc(grid);
  bc.set(0, Side::lower, Boundary::inflow([](const Point& x, double) { return parabola(x); }));
  bc.set(0, Side::upper, Boundary::outflow());
  NavierStokes flow(grid, bc, {1.0, ViscosityModel::newtonian(1e-3), {0, 0, 0}},
                    {.cfl = 0.5, .dt_max = 0.05, .dt_initial = 1e-3});
  const auto bodies = make_bodies(grid, method);
  const auto body =
      bodies->add({geometry::Cylinder(D / 2, 3 * T),
                   geometry::Pose({0.2 + shift.x() * h, 0.2 + shift.y() * h, T / 2}, Eigen::Quaterniond::Identity())});
  flow.set_velocity(parabola);
  const double to_coefficient = 2 / (D * T * Umean * Umean);
  FluidRun run{"DFG 2D-1 C_D", "D/h=" + std::to_string(cells_per_diameter), label(method)};
  // Steady: C_D moves by less than 1e-4 of itself over half a time unit (at most t = 12).
  double cd = 0;
  run.steps = run_to_steady(flow, bodies->for_step(), 0.5, 12, 1e-4,
                            [&] { return cd = to_coefficient * bodies->loads(flow)[body].force[0]; });
  run.check = to_coefficient * bodies->loads(flow)[body].force[1];
  const auto n = grid.cells();
  run.cells = static_cast<long>(n[0] * n[1] * n[2]);
  run.value = cd;
  run.reference = kDrag;
  run.seconds = MPI_Wtime() - start;
  return run;
}

namespace {

constexpr double kRadius = 0.2, kViscosity = 10, kDrive = 10;

// The steps' no-slip corrections and wall seconds per stage, summed.
struct Towing {
  int corrections = 0;
  StageSeconds seconds;
};

// A speed that rises from rest to one over the time `rise` as 3 x^2 - 2 x^3 (x = t / rise),
// and the distance it covers by t; a rise of 0 starts at full speed.
struct SpeedRise {
  double rise = 0;
  double speed(double t) const {
    const double x = rise > 0 ? std::min(t / rise, 1.0) : 1.0;
    return x * x * (3 - 2 * x);
  }
  double distance(double t) const {
    if (t >= rise) return t - rise / 2;
    const double x = t / rise;
    return rise * x * x * x * (1 - x / 2);
  }
};

// Moves body 0 from `start` at `velocity` (reached over `rise`), one fluid step of dt at a
// time, and after step k calls after(k, where the body was when the step's load acted)
// until it returns false: at the step's end, or at t_n + theta dt where the immersed
// boundary spreads its force from there (IbmOptions::spread_at_theta).
template <typename After>
Towing tow(BodyTreatment& bodies, NavierStokes& flow, const Eigen::Vector3d& start, const Eigen::Vector3d& velocity,
           double dt, After after, SpeedRise rise = {}) {
  Towing out;
  const auto* ibm = dynamic_cast<const ImmersedBoundary*>(&bodies);
  const double theta = ibm && ibm->options().spread_at_theta ? flow.time_step_options().theta : 1.0;
  for (int k = 1;; ++k) {
    bodies.move(0, geometry::Pose(start + rise.distance(k * dt) * velocity, Eigen::Quaterniond::Identity()),
                rise.speed(k * dt) * velocity, Eigen::Vector3d::Zero());
    const StepReport report = flow.step(dt, bodies.for_step());
    out.corrections += report.no_slip_corrections;
    out.seconds += report.seconds;
    if (!after(k, Eigen::Vector3d(start + rise.distance((k - 1 + theta) * dt) * velocity))) return out;
  }
}

// The value of samples `y`, taken where a coordinate fell through `x`, at `at`: linear
// between the two samples around it, the last one's beyond them.
double between(const std::vector<double>& x, const std::vector<double>& y, double at) {
  for (std::size_t i = 1; i < x.size(); ++i)
    if (x[i] <= at) {
      const double w = (x[i - 1] - at) / (x[i - 1] - x[i]);
      return (1 - w) * y[i - 1] + w * y[i];
    }
  return y.back();
}

// The mean of samples `y` over the stretch of `x` from `a` to `b`, `y` linear between the
// samples (whichever way `x` runs).
double mean_between(const std::vector<double>& x, const std::vector<double>& y, double a, double b) {
  const double lo = std::min(a, b), hi = std::max(a, b);
  double integral = 0;
  for (std::size_t i = 1; i < x.size(); ++i) {
    const double x0 = std::min(x[i - 1], x[i]), x1 = std::max(x[i - 1], x[i]);
    const double from = std::max(x0, lo), to = std::min(x1, hi);
    if (to <= from) continue;
    const auto at = [&](double v) { return y[i - 1] + (y[i] - y[i - 1]) * (v - x[i - 1]) / (x[i] - x[i - 1]); };
    integral += 0.5 * (at(from) + at(to)) * (to - from);
  }
  return integral / (hi - lo);
}

// Steady flow through the periodic array in the unit box on n^3 cells. The incremental
// scheme's slow splitting mode decays per step, and far more slowly at large viscous
// numbers (bench/fluid_accuracy/README.md, "Accuracy study"), hence steps of nu dt / h^2 = 1 by default;
// the steady state does not depend on them (the immersed boundary's Hasimoto drag by
// 0.003 % from nu dt / h^2 = 0.08 to 1).
class StokesArray {
 public:
  // `drive`: the body force per mass on the fluid along x (rho = 1).
  StokesArray(int n, const BodyOptions& method, const Eigen::Vector3d& centre, const StokesStepping& stepping,
              double drive = kDrive)
      : n_(n),
        dt_(dt(n, stepping.viscous_number)),
        centre_(centre),
        grid_(PETSC_COMM_WORLD,
              {Axis::uniform(n, 0, 1, true), Axis::uniform(n, 0, 1, true), Axis::uniform(n, 0, 1, true)}),
        bc_(grid_),
        flow_(grid_, bc_, {1.0, ViscosityModel::newtonian(kViscosity), {drive, 0, 0}},
              {.cfl = 0.5, .dt_max = dt_, .dt_initial = dt_, .theta = stepping.theta}),
        bodies_(make_bodies(grid_, method)) {
    bodies_->add({geometry::Sphere(kRadius), geometry::Pose(centre, Eigen::Quaterniond::Identity())});
    flow_.set_velocity([](const Point&) { return Point{0, 0, 0}; });
  }

  // Steps to the steady state: until the mean velocity changes by less than 2e-5 of itself
  // over 500 steps (at most max_steps). On 16^3 cells the change per 100 steps shrank by a
  // factor 0.79 each time, so what is left to come is below 1e-5 of U by then.
  int run_to_steady(int max_steps) {
    int steps = 0;
    bool steady = false;
    for (double before = 0; !steady && steps < max_steps;) {
      for (int k = 0; k < 500; ++k) flow_.step(dt_, bodies_->for_step());
      steps += 500;
      velocity_ = mean_u(flow_, double(n_) * n_ * n_);
      steady = std::abs(velocity_ - before) < 2e-5 * std::abs(velocity_);
      before = velocity_;
    }
    if (!steady)
      PetscPrintf(PETSC_COMM_WORLD, "warning: Hasimoto %d^3 stopped at %d steps short of the steady state\n", n_,
                  steps);
    force_ = bodies_->loads(flow_)[0].force[0];
    return steps;
  }

  // The steady flow seen from a frame moving at -U along x (U the mean velocity now): the
  // sphere towed at -U through fluid at rest far off, `cells` cell widths; its drag
  // averaged over the last `averaged` of them (whole cells, over which the kernel's
  // ripple averages out).
  double towed_drag(int cells, int averaged) {
    const double towed = -velocity_, h = 1.0 / n_;
    flow_.shift_frame({towed, 0, 0});
    auto steps_for = [&](int c) { return static_cast<int>(std::lround(c * h / (std::abs(towed) * dt_))); };
    const int steps = steps_for(cells), from = steps_for(cells - averaged);
    double sum = 0;
    tow(*bodies_, flow_, centre_, {towed, 0, 0}, dt_, [&](int k, const Eigen::Vector3d&) {
      if (k > from) sum += bodies_->loads(flow_)[0].force[0];
      return k < steps;
    });
    return sum / (steps - from);
  }

  static double dt(int n, double viscous_number) { return viscous_number / (kViscosity * n * n); }
  double time_step() const { return dt_; }
  double velocity() const { return velocity_; }
  double force() const { return force_; }
  double imposed_fraction() const {
    const auto* staircase = dynamic_cast<const FictitiousBoundary*>(bodies_.get());
    if (!staircase) return 0;
    double imposed = static_cast<double>(staircase->imposed_faces().owned(0).size());
    MPI_Allreduce(MPI_IN_PLACE, &imposed, 1, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD);
    return imposed / (double(n_) * n_ * n_);
  }
  long cells() const { return static_cast<long>(n_) * n_ * n_; }

 private:
  int n_;
  double dt_;
  Eigen::Vector3d centre_;
  Grid grid_;
  BoundaryConditions bc_;
  NavierStokes flow_;
  std::unique_ptr<BodyTreatment> bodies_;
  double velocity_ = 0, force_ = 0;
};

// Hasimoto's drag coefficient 6 pi mu a K(c) of the array's sphere (rho = 1, L = 1).
double hasimoto_resistance() {
  const double c = 4.0 / 3.0 * std::numbers::pi * kRadius * kRadius * kRadius;  // V / L^3
  return 6 * std::numbers::pi * kViscosity * kRadius / (1 - 1.7601 * std::cbrt(c) + c - 1.5593 * c * c);
}

double hasimoto_error(double velocity) { return kDrive / (hasimoto_resistance() * velocity) - 1; }

}  // namespace

FluidRun hasimoto_sphere(int n, const BodyOptions& method, const Eigen::Vector3d& centre,
                         const StokesStepping& stepping) {
  const double start = MPI_Wtime();
  StokesArray array(n, method, centre, stepping);
  FluidRun run{"Hasimoto F", std::to_string(n) + "^3", label(method)};
  run.cells = array.cells();
  run.steps = array.run_to_steady(stepping.max_steps);
  run.value = kDrive;  // rho f L^3
  run.reference = kDrive / (1 + hasimoto_error(array.velocity()));
  run.check = array.force() / (kDrive * (1 - array.imposed_fraction()));
  run.seconds = MPI_Wtime() - start;
  return run;
}

Smoothness sphere_through_a_cell(const BodyOptions& method, int steps_per_cell) {
  constexpr int n = 20;
  constexpr double h = 1.0 / n, a = 4 * h, nu = 10, dt = 1e-3;
  const double start_time = MPI_Wtime();
  const Axis axis = Axis::uniform(n, 0, 1, false);
  Grid grid(PETSC_COMM_WORLD, {axis, axis, axis});
  BoundaryConditions bc(grid);
  NavierStokes flow(grid, bc, {1.0, ViscosityModel::newtonian(nu), {0, 0, 0}}, {.dt_max = dt, .dt_initial = dt});
  const Eigen::Vector3d direction = Eigen::Vector3d(1.0, 0.37, 0.21).normalized();
  const Eigen::Vector3d velocity = direction * h / (steps_per_cell * dt * direction.x());  // one cell along x
  // Three cells of travel to let the impulsive start pass, then the cell measured, ending
  // off the box's centre by a generic offset.
  const Eigen::Vector3d end = Eigen::Vector3d(0.5, 0.5, 0.5) + Eigen::Vector3d(0.13, 0.41, 0.77) * h;
  const int warm = 3 * steps_per_cell, measured = steps_per_cell;
  const Eigen::Vector3d start = end - (warm + measured) * dt * velocity;
  const auto bodies = make_bodies(grid, method);
  bodies->add({geometry::Sphere(a), geometry::Pose(start, Eigen::Quaterniond::Identity()), velocity});
  flow.set_velocity([](const Point&) { return Point{0, 0, 0}; });
  std::vector<double> time, drag;
  tow(*bodies, flow, start, velocity, dt, [&](int k, const Eigen::Vector3d&) {
    if (k > warm) {
      time.push_back(k * dt);
      drag.push_back(-bodies->loads(flow)[0].force.dot(direction));
    }
    return k < warm + measured;
  });
  // Least-squares quadratic through the drag (normal equations on t - mean: well scaled).
  const double tm = (time.front() + time.back()) / 2;
  Eigen::MatrixXd basis(time.size(), 3);
  Eigen::VectorXd values(time.size());
  for (std::size_t i = 0; i < time.size(); ++i) {
    const double t = time[i] - tm;
    basis.row(static_cast<Eigen::Index>(i)) << 1, t, t * t;
    values[static_cast<Eigen::Index>(i)] = drag[i];
  }
  const Eigen::VectorXd fit = basis.colPivHouseholderQr().solve(values);
  const Eigen::VectorXd residual = values - basis * fit;
  Smoothness s;
  s.mean_drag = values.mean();
  s.spread = residual.cwiseAbs().maxCoeff() / s.mean_drag;
  for (Eigen::Index i = 1; i < residual.size(); ++i)
    s.jump = std::max(s.jump, std::abs(residual[i] - residual[i - 1]) / s.mean_drag);
  s.steps = warm + measured;
  s.seconds = MPI_Wtime() - start_time;
  return s;
}

namespace {

// The case's step with `stepping`'s theta and pressure update.
TimeStepOptions fixed_step(double dt, const TimeStepOptions& stepping) {
  TimeStepOptions fixed = stepping;
  fixed.cfl = 10;
  fixed.dt_max = fixed.dt_initial = dt;
  return fixed;
}

}  // namespace

Towed towed_sphere(const BodyOptions& method, int cells_per_diameter, double cells_per_step, double reynolds,
                   double rise, const TimeStepOptions& stepping) {
  const int n = static_cast<int>(std::lround(6.7 * cells_per_diameter));
  const int height = static_cast<int>(std::lround(10.7 * cells_per_diameter));
  // Started 8/3 diameters below the lid (0.4 m for ten Cate's 15 mm sphere scaled to 0.15).
  const double h = 1.0 / n, d = cells_per_diameter * h, U = 1, z_start = height * h - 8.0 / 3.0 * d,
               z_measure = z_start - 3.3 * d;
  const double nu = U * d / reynolds;
  const double start_time = MPI_Wtime();
  Grid grid(PETSC_COMM_WORLD, {Axis::uniform(n, 0, 1, false), Axis::uniform(n, 0, 1, false),
                               Axis::uniform(height, 0, height * h, false)});
  BoundaryConditions bc(grid);
  Towed out;
  out.cells_per_step = cells_per_step;
  const double dt = cells_per_step * h / U;
  out.viscous_number = nu * dt / (h * h);
  NavierStokes flow(grid, bc, {1.0, ViscosityModel::newtonian(nu), {0, 0, 0}}, fixed_step(dt, stepping));
  const auto bodies = make_bodies(grid, method);
  const Eigen::Vector3d velocity(0, 0, -U);
  // Off the cells' centres and faces by a generic amount.
  const Eigen::Vector3d start(0.5 + 0.31 * h, 0.5 + 0.17 * h, z_start);
  bodies->add({geometry::Sphere(d / 2), geometry::Pose(start, Eigen::Quaterniond::Identity()), velocity});
  flow.set_velocity([](const Point&) { return Point{0, 0, 0}; });
  std::vector<double> heights, drags;
  const Towing towing = tow(
      *bodies, flow, start, velocity, dt,
      [&](int k, const Eigen::Vector3d& at) {
        out.steps = k;
        heights.push_back(at.z());
        drags.push_back(bodies->loads(flow)[0].force.z());
        return at.z() > z_measure;
      },
      SpeedRise{rise * d / U});
  out.drag = mean_between(heights, drags, z_measure + h, z_measure);
  out.corrections = static_cast<double>(towing.corrections) / out.steps;
  out.seconds = MPI_Wtime() - start_time;
  return out;
}

WallApproach sphere_approaching_a_wall(const BodyOptions& method, int cells_per_diameter, double viscous_number,
                                       double reynolds, const std::vector<double>& gaps,
                                       const TimeStepOptions& stepping, const WallApproachBox& box) {
  const int n = static_cast<int>(std::lround(box.diameters * cells_per_diameter));
  const double h = 1.0 / n, a = 0.5 * cells_per_diameter * h, U = 1, nu = U * 2 * a / reynolds;
  const double start_time = MPI_Wtime();
  const Axis axis = Axis::uniform(n, 0, 1, false);
  Grid grid(PETSC_COMM_WORLD, {axis, axis, axis});
  BoundaryConditions bc(grid);
  WallApproach out;
  const double dt = viscous_number * h * h / nu;
  out.cells_per_step = U * dt / h;
  NavierStokes flow(grid, bc, {1.0, ViscosityModel::newtonian(nu), {0, 0, 0}}, fixed_step(dt, stepping));
  const auto bodies = make_bodies(grid, method);
  const Eigen::Vector3d velocity(0, 0, -U);
  // Off the cells' centres and faces by a generic amount.
  const Eigen::Vector3d start(0.5 + 0.31 * h, 0.5 + 0.17 * h, (box.start_gap + 1) * a + 0.42 * h);
  bodies->add({geometry::Sphere(a), geometry::Pose(start, Eigen::Quaterniond::Identity()), velocity});
  flow.set_velocity([](const Point&) { return Point{0, 0, 0}; });
  const double stokes = 6 * std::numbers::pi * nu * a * U;
  const Towing towing = tow(*bodies, flow, start, velocity, dt, [&](int k, const Eigen::Vector3d& at) {
    out.steps = k;
    out.sampled_gaps.push_back(at.z() / a - 1);
    out.sampled_factors.push_back(bodies->loads(flow)[0].force.z() / stokes);
    return out.sampled_gaps.back() > gaps.back();
  });
  for (double gap : gaps) out.factors.push_back(between(out.sampled_gaps, out.sampled_factors, gap));
  out.corrections = static_cast<double>(towing.corrections) / out.steps;
  out.stages = towing.seconds;
  out.seconds = MPI_Wtime() - start_time;
  return out;
}

double error_against(const WallApproach& run, const WallApproach& finest, double gap) {
  const auto error_at = [&](std::size_t i) {
    return run.sampled_factors[i] / between(finest.sampled_gaps, finest.sampled_factors, run.sampled_gaps[i]) - 1;
  };
  for (std::size_t i = 1; i < run.sampled_gaps.size(); ++i)
    if (run.sampled_gaps[i] <= gap) {
      if (run.sampled_gaps[i] < finest.sampled_gaps.back()) return error_at(i - 1);
      const double w = (run.sampled_gaps[i - 1] - gap) / (run.sampled_gaps[i - 1] - run.sampled_gaps[i]);
      return (1 - w) * error_at(i - 1) + w * error_at(i);
    }
  return error_at(run.sampled_gaps.size() - 1);
}

double brenner_wall_factor(double gap) {
  // lambda = 4/3 sinh(alpha) sum_n n (n + 1) / ((2n - 1)(2n + 3)) [(2 sinh((2n + 1) alpha)
  // + (2n + 1) sinh(2 alpha)) / (4 sinh^2((n + 1/2) alpha) - (2n + 1)^2 sinh^2(alpha)) - 1],
  // cosh(alpha) the centre's height over the radius; the terms fall as exp(-2 n alpha).
  const double alpha = std::acosh(1 + gap), s = std::sinh(alpha);
  double sum = 0;
  for (int n = 1; n < 100000; ++n) {
    const double m = 2 * n + 1, sh = std::sinh((n + 0.5) * alpha);
    const double term = n * (n + 1.0) / ((2 * n - 1.0) * (2 * n + 3.0)) *
                        ((2 * std::sinh(m * alpha) + m * std::sinh(2 * alpha)) / (4 * sh * sh - m * m * s * s) - 1);
    if (!std::isfinite(term)) break;
    sum += term;
    if (std::abs(term) < 1e-14 * std::abs(sum)) break;
  }
  return 4.0 / 3.0 * s * sum;
}

DuctDrag sphere_in_sliding_duct(const BodyOptions& method, int cells_per_diameter, double reynolds) {
  constexpr double d = 1, U = 1, width = 20.0 / 3, upstream = 5, downstream = 11;
  const double nu = U * d / reynolds, h = d / cells_per_diameter, start_time = MPI_Wtime();
  const int across = static_cast<int>(std::lround(width / h));
  const int along = static_cast<int>(std::lround((upstream + downstream) / h));
  Grid grid(PETSC_COMM_WORLD, {Axis::uniform(across, 0, width, false), Axis::uniform(across, 0, width, false),
                               Axis::uniform(along, 0, along * h, false)});
  BoundaryConditions bc(grid);
  const Point stream{0, 0, U};
  bc.set(2, Side::lower, Boundary::inflow([stream](const Point&, double) { return stream; }));
  bc.set(2, Side::upper, Boundary::outflow());
  for (int axis = 0; axis < 2; ++axis)
    for (Side side : {Side::lower, Side::upper}) bc.set(axis, side, Boundary::moving_wall(stream));
  NavierStokes flow(grid, bc, {1.0, ViscosityModel::newtonian(nu), {0, 0, 0}},
                    {.cfl = 0.5, .dt_max = 0.5 * h / U, .dt_initial = 0.5 * h / U});
  const auto bodies = make_bodies(grid, method);
  // Off the duct's axis and the cells' faces by a generic amount.
  const Eigen::Vector3d centre =
      Eigen::Vector3d(width / 2, width / 2, upstream) + Eigen::Vector3d(0.31, 0.17, 0.42) * h;
  bodies->add({geometry::Sphere(d / 2), geometry::Pose(centre, Eigen::Quaterniond::Identity())});
  flow.set_velocity([stream](const Point&) { return stream; });
  DuctDrag out;
  // Steady: the drag moves by less than 1e-5 of itself over one d / U (at most 200).
  double drag = 0;
  out.steps =
      run_to_steady(flow, bodies->for_step(), 1, 200, 1e-5, [&] { return drag = bodies->loads(flow)[0].force.z(); });
  out.factor = drag / (3 * std::numbers::pi * nu * U * d);
  out.cells = static_cast<long>(across) * across * along;
  out.seconds = MPI_Wtime() - start_time;
  return out;
}

MovingFrame moving_frame(int n, const BodyOptions& method, double reynolds, double cells_per_step) {
  const double start = MPI_Wtime();
  const double h = 1.0 / n, estimate = reynolds * kViscosity / (2 * kRadius);  // U of Stokes drag
  MovingFrame out;
  out.viscous_number = cells_per_step * kViscosity / (estimate * h);
  // Off the cell's centre by a generic amount, two cells ahead: the tow of four cells
  // keeps the sphere and its kernels off the periodic boundary.
  const Eigen::Vector3d centre = Eigen::Vector3d(0.5 + 2 * h, 0.5, 0.5) + Eigen::Vector3d(0.31, 0.17, 0.42) * h;
  StokesArray array(n, method, centre, {.viscous_number = out.viscous_number, .theta = 0.5},
                    hasimoto_resistance() * estimate);
  array.run_to_steady(40000);
  out.fixed_drag = array.force();
  out.reynolds = array.velocity() * 2 * kRadius / kViscosity;
  out.cells_per_step = array.velocity() * array.time_step() / h;
  out.moving_drag = array.towed_drag(4, 2);
  out.seconds = MPI_Wtime() - start;
  return out;
}

}  // namespace cosim::bench
