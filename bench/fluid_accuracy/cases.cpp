#include "cases.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include "channel.hpp"
#include "fluid/fictitious_boundary.hpp"

namespace cosim::bench {
namespace {

using namespace cosim::fluid;

std::string alpha_label(int subsamples) {
  return subsamples == 1 ? "point" : std::to_string(subsamples) + "^3 sub";
}

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

double mean_u(const NavierStokes& flow, double cells) {
  PetscScalar total = 0;
  VecSum(flow.velocity(0), &total);
  return total / cells;
}

}  // namespace

FluidRun dfg_cylinder(int cells_per_diameter, int subsamples, double* lift) {
  using namespace dfg;
  const double start = MPI_Wtime();
  const Axis y = across(cells_per_diameter);
  Grid grid(PETSC_COMM_WORLD, {along_channel(H / y.cells()), y, layer()});
  BoundaryConditions bc(grid);
  bc.set(0, Side::lower, Boundary::inflow([](const Point& x, double) { return parabola(x); }));
  bc.set(0, Side::upper, Boundary::outflow());
  NavierStokes flow(grid, bc, {1.0, ViscosityModel::newtonian(1e-3), {0, 0, 0}},
                    {.cfl = 0.5, .dt_max = 0.05, .dt_initial = 1e-3});
  FictitiousBoundary fbm(grid, {.subsamples = subsamples});
  const auto body = fbm.add({geometry::Cylinder(D / 2, 3 * T),
                             geometry::Pose({0.2, 0.2, T / 2}, Eigen::Quaterniond::Identity())});
  flow.impose(&fbm.imposed_faces());
  flow.set_velocity(parabola);
  const double to_coefficient = 2 / (D * T * Umean * Umean);
  FluidRun run{"DFG 2D-1 C_D", "D/h=" + std::to_string(cells_per_diameter), alpha_label(subsamples)};
  // Steady: C_D moves by less than 1e-4 of itself over half a time unit (at most t = 12).
  double cd = 0;
  for (double t = 0.5; t <= 12; t += 0.5) {
    run.steps += static_cast<int>(flow.advance_to(t).size());
    const double before = cd;
    cd = to_coefficient * fbm.loads(flow)[body].force[0];
    if (std::abs(cd - before) < 1e-4 * cd) break;
  }
  if (lift) *lift = to_coefficient * fbm.loads(flow)[body].force[1];
  const auto n = grid.cells();
  run.cells = static_cast<long>(n[0] * n[1] * n[2]);
  run.value = cd;
  run.reference = kDrag;
  run.seconds = MPI_Wtime() - start;
  return run;
}

FluidRun hasimoto_sphere(int n, int subsamples) {
  constexpr double a = 0.2, mu = 10, f = 10;
  const double start = MPI_Wtime();
  const Axis periodic = Axis::uniform(n, 0, 1, true);
  Grid grid(PETSC_COMM_WORLD, {periodic, periodic, periodic});
  BoundaryConditions bc(grid);
  NavierStokes flow(grid, bc, {1.0, ViscosityModel::newtonian(mu), {f, 0, 0}},
                    {.cfl = 0.5, .dt_max = 0.002, .dt_initial = 0.002, .theta = 1.0});
  FictitiousBoundary fbm(grid, {.subsamples = subsamples});
  const auto body = fbm.add({geometry::Sphere(a), geometry::Pose({0.5, 0.5, 0.5}, Eigen::Quaterniond::Identity())});
  flow.impose(&fbm.imposed_faces());
  flow.set_velocity([](const Point&) { return Point{0, 0, 0}; });
  const double cells = double(n) * n * n;
  FluidRun run{"Hasimoto F", std::to_string(n) + "^3", alpha_label(subsamples)};
  run.cells = static_cast<long>(cells);
  // Steady: U and F each change by less than 1e-5 of themselves in a step (at most 400).
  double u = 0, drag = 0;
  for (bool steady = false; !steady && run.steps < 400; ++run.steps) {
    flow.step();
    const double u1 = mean_u(flow, cells), drag1 = fbm.loads(flow)[body].force[0];
    steady = std::abs(u1 - u) < 1e-5 * u1 && std::abs(drag1 - drag) < 1e-5 * drag1;
    u = u1;
    drag = drag1;
  }
  const double volume = 4.0 / 3.0 * std::numbers::pi * a * a * a;  // c = V / L^3, L = 1
  const double k = 1 / (1 - 1.7601 * std::cbrt(volume) + volume - 1.5593 * volume * volume);
  run.value = drag + f * volume;
  run.reference = 6 * std::numbers::pi * mu * a * u * k;
  run.seconds = MPI_Wtime() - start;
  return run;
}

}  // namespace cosim::bench
