// An inflow face `within` a container: the flow rate through the face is the profile's over
// the container's cross section, nothing enters outside it, and a bad `within` is refused
// naming file, key and value.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include <petscsys.h>

#include "coupler/scene/error.hpp"
#include "coupler/scene/scene.hpp"
#include "fluid/ibm/immersed_boundary.hpp"
#include "fluid/navier_stokes/navier_stokes.hpp"
#include "fluid/program/confined_inflow.hpp"
#include "fluid/program/scene_fluid.hpp"

namespace cosim::fluid::program {

using grid::Axis;
using grid::Boundary;
using grid::BoundaryConditions;
using grid::for_each_index;
using grid::Grid;
using grid::Index;
using grid::Point;
using grid::Side;
using ibm::ImmersedBoundary;
using navier_stokes::NavierStokes;
using viscous::ViscosityModel;

namespace {

// A round column of radius `radius` centred at (cx, cy) in a box of n x n x 8 cells, fed
// through its floor (`inflow` holds the z_min face's keys) and open at the top.
std::string column_scene(
    double radius, double cx, double cy, int n, const std::string& inflow,
    const std::string& column_shape = "type: cylinder, radius: {r}, height: 0.3, container: true") {
  std::string shape = column_shape;
  if (const auto at = shape.find("{r}"); at != std::string::npos) shape.replace(at, 3, std::to_string(radius));
  return "time: {end: 0.1}\ncoupling: {window: 0.01}\n"
         "domain: {min: [-0.05, -0.05, 0], max: [0.05, 0.05, 0.2]}\n"
         "bodies:\n"
         "  - {name: column, fixed: true, shape: {" +
         shape + "}, position: [" + std::to_string(cx) + ", " + std::to_string(cy) +
         ", 0.1]}\n"
         "  - {name: bead, shape: {type: sphere, radius: 0.003}, material: {density: 2000}, position: [" +
         std::to_string(cx) + ", " + std::to_string(cy) +
         ", 0.1]}\n"
         "effects: [hydrodynamics]\n"
         "participants:\n"
         "  rigidbody: {dt: 0.01}\n"
         "  fluid:\n"
         "    dt: 0.01\n"
         "    options:\n"
         "      density: 1000\n"
         "      viscosity: {model: newtonian, mu: 1.0e-3}\n"
         "      grid: {cells: [" +
         std::to_string(n) + ", " + std::to_string(n) +
         ", 8]}\n"
         "      boundaries:\n"
         "        z_min: {" +
         inflow +
         "}\n"
         "        z_max: {type: outflow}\n";
}

FluidSetup setup_of(const std::string& text) { return fluid_setup(scene::load_scene_from_string(text, "s.yaml")); }

// The flow rate through the z_min face, summed over its cells' centres, and the largest
// speed on a cell whose whole face lies outside the circle of `radius` about (cx, cy).
struct FaceFlow {
  double rate = 0, outside = 0;
};

FaceFlow face_flow(const FluidSetup& s, double radius, double cx, double cy) {
  const fluid::grid::Boundary& floor = s.boundaries[4];
  EXPECT_EQ(floor.kind, fluid::grid::BoundaryKind::inflow);
  FaceFlow out;
  const fluid::grid::Axis &x = s.axes[0], &y = s.axes[1];
  for (int j = 0; j < y.cells(); ++j)
    for (int i = 0; i < x.cells(); ++i) {
      const fluid::grid::Point u = floor.velocity({x.centre(i), y.centre(j), 0.0}, 0.0);
      out.rate += u[2] * x.width(i) * y.width(j);
      const double nearest = std::hypot(std::max({x.face(i) - cx, cx - x.face(i + 1), 0.0}),
                                        std::max({y.face(j) - cy, cy - y.face(j + 1), 0.0}));
      if (nearest > radius) out.outside = std::max(out.outside, std::abs(u[2]));
    }
  return out;
}

// Calibrated on nothing: the flow rate follows from the sampled fractions, checked at radii
// and offsets that put the wall across the cells in different ways, on a coarse and a fine
// face, and on a box-shaped basket whose section the cells cut off-grid.
TEST(ConfinedInflow, FlowRateIsTheProfilesOverTheSection) {
  const double u = 0.12;
  for (const int n : {20, 50})
    for (const double radius : {0.04, 0.0337})
      for (const double offset : {0.0, 0.0013}) {
        const FluidSetup s =
            setup_of(column_scene(radius, offset, -offset, n, "type: inflow, velocity: [0, 0, 0.12], within: column"));
        const FaceFlow f = face_flow(s, radius, offset, -offset);
        const double expected = u * std::numbers::pi * radius * radius;
        // Sampling 16 x 16 per cell: the cut cells' fractions within 1/16 each, and their
        // errors of both signs cancel along the rim.
        EXPECT_NEAR(f.rate / expected, 1.0, 0.005) << "n " << n << " radius " << radius << " offset " << offset;
        EXPECT_EQ(f.outside, 0.0) << "n " << n << " radius " << radius;
      }
  const FluidSetup basket =
      setup_of(column_scene(0, 0.0011, 0.0, 20, "type: inflow, velocity: [0, 0, 0.12], within: column",
                            "type: box, half_extents: [0.0302, 0.0217, 0.15], container: true"));
  // A straight wall along the grid's lines does not cancel: it may be off by half a sample
  // width all along its length, here 1.2 % of the section.
  const double perimeter = 2 * (0.0604 + 0.0434), area = 0.0604 * 0.0434, sample = 0.1 / 20 / 16;
  EXPECT_NEAR(face_flow(basket, 0, 0.0011, 0.0).rate / (u * area), 1.0, perimeter * sample / 2 / area);
}

// Without `within` the whole face feeds the box, corners included.
TEST(ConfinedInflow, AnUnconfinedInflowFeedsTheWholeFace) {
  const FluidSetup s = setup_of(column_scene(0.04, 0, 0, 20, "type: inflow, velocity: [0, 0, 0.12]"));
  EXPECT_NEAR(face_flow(s, 0.04, 0, 0).rate, 0.12 * 0.1 * 0.1, 1e-12);
}

TEST(ConfinedInflow, RefusesWhatIsNotAContainersInside) {
  struct Bad {
    std::string inflow, shape, problem;
  };
  const std::string cylinder = "type: cylinder, radius: 0.04, height: 0.3, container: true";
  const Bad cases[] = {
      {"type: inflow, velocity: [0, 0, 0.1], within: pipe", cylinder, "no body of that name"},
      {"type: inflow, velocity: [0, 0, 0.1], within: bead", cylinder, "not a container"},
      {"type: inflow, velocity: [0, 0, 0.1], profile: parabolic, within: column", cylinder, "profile uniform"},
      // Its floor cap at z = 0.05 is inside the box: none of the face is inside.
      {"type: inflow, velocity: [0, 0, 0.1], within: column",
       "type: cylinder, radius: 0.04, height: 0.1, container: true", "no part of the face"},
  };
  for (const Bad& c : cases) {
    try {
      setup_of(column_scene(0.04, 0, 0, 10, c.inflow, c.shape));
      ADD_FAILURE() << "accepted " << c.inflow << " with " << c.shape;
    } catch (const scene::SceneError& e) {
      EXPECT_EQ(e.file, "s.yaml");
      EXPECT_EQ(e.key, "participants.fluid.options.boundaries.z_min.within") << e.what();
      EXPECT_NE(std::string(e.what()).find(c.problem), std::string::npos) << e.what();
    }
  }
}

// A plug u0 at Reynolds number u0 D / nu fed into a round column of D/h 12, three diameters
// long, its axis off the grid's lines, run for `transits` times the column's length over u0:
// at two diameters up, the flow rate through the column's section and outside it (as
// fractions of the inflow), the centreline speed and the largest speed in the held solid
// (over u0).
struct ColumnFlow {
  double inside, outside, centre, held;
};

ColumnFlow plug_into_a_round_column(double reynolds, double transits) {
  const double radius = 0.5, nu = 1.0, u0 = reynolds * nu / (2 * radius);
  const int across = 12, margin = 6, length = 3 * across;
  const double h = 2 * radius / across, side = (across + margin) * h;
  const Axis box = Axis::uniform(across + margin, -side / 2, side / 2, false);
  const std::vector<Axis> axes{box, box, Axis::uniform(length, 0, length * h, false)};
  Grid grid(PETSC_COMM_WORLD, {axes[0], axes[1], axes[2]});
  // The caps beyond both ends of the box.
  const geometry::Container column(geometry::Cylinder(radius, 2 * length * h));
  const geometry::Pose pose({0.29 * h, -0.13 * h, length * h / 2}, Eigen::Quaterniond::Identity());
  BoundaryConditions bc(grid);
  bc.set(2, Side::lower,
         Boundary::inflow(confined_inflow(
             [&](const Point&, double) {
               return Point{0, 0, u0};
             },
             column, pose, 2, Side::lower, axes)));
  bc.set(2, Side::upper, Boundary::outflow());
  const double dt = std::min(h * h / nu, 0.5 * h / u0);
  NavierStokes flow(grid, bc, {1.0, ViscosityModel::newtonian(nu), {0, 0, 0}},
                    {.cfl = 10, .dt_max = dt, .dt_initial = dt});
  ImmersedBoundary bodies(grid, {});
  bodies.add({column, pose});
  flow.set_velocity([](const Point&) { return Point{0, 0, 0}; });
  const double end = transits * length * h / u0;
  while (flow.time() < end - dt / 2) flow.step(dt, bodies.for_step());

  DM dm = grid.velocity_dm(2);
  const PetscScalar*** w = nullptr;
  DMDAVecGetArrayRead(dm, flow.velocity(2), &w);
  ColumnFlow out{0, 0, 0, 0};
  const int level = 2 * across;  // two diameters up
  for_each_index(grid.owned(dm), [&](const Index& p) {
    if (p[2] != level) return;
    const Point x = grid.position(2, p);
    const double r = std::hypot(x[0] - pose.position().x(), x[1] - pose.position().y());
    const double u = w[p[2]][p[1]][p[0]];
    (r < radius ? out.inside : out.outside) += u * h * h;
    if (r < h / 2) out.centre = std::max(out.centre, u);
    if (r > radius + 3 * h) out.held = std::max(out.held, std::abs(u));
  });
  DMDAVecRestoreArrayRead(dm, flow.velocity(2), &w);
  MPI_Allreduce(MPI_IN_PLACE, &out.inside, 2, MPI_DOUBLE, MPI_SUM, grid.comm());
  MPI_Allreduce(MPI_IN_PLACE, &out.centre, 2, MPI_DOUBLE, MPI_MAX, grid.comm());
  const double inflow = u0 * std::numbers::pi * radius * radius;
  out.inside /= inflow;
  out.outside /= inflow;
  out.centre /= u0;
  out.held /= u0;
  PetscPrintf(
      PETSC_COMM_WORLD,
      "column D/h %d, Re %.0f: flow rate through the column %+.4f of the inflow's, outside it %+.4f; centreline "
      "%.4f u0, held %.2g u0\n",
      across, reynolds, out.inside - 1, out.outside, out.centre, out.held);
  return out;
}

// Guards against: a plug fed into a round column through the whole floor of the box around it
// (the held corners refusing it), and fluid leaking between the column and the held solid.
// At Re 5 the plug develops into Poiseuille's flow (entry length about (0.6 + 0.056 Re) D)
// within two diameters: the flow rate through the column is the inflow's and the centreline
// speed twice u0.
TEST(ConfinedInflow, PlugDevelopsIntoPoiseuillesFlowInARoundColumn) {
  // Through the column once: the slowest viscous mode down to 1e-6 of itself by 2.4 R^2 / nu.
  const ColumnFlow flow = plug_into_a_round_column(5, 1);
  EXPECT_NEAR(flow.inside, 1.0, 0.02);
  EXPECT_NEAR(flow.centre, 2.0, 0.06);
  EXPECT_LT(flow.held, 1e-3);
}

// At Re 300 the plug is still developing two diameters up, driven hardest next to the wall,
// and part of it passes outside the wall: through the faces between the markers' kernels
// and the held solid, which nothing forces (docs/limits.md). Measured: 3.7 % of the flow at
// D/h 12; this guards against more.
TEST(ConfinedInflow, FlowPastTheColumnsWallAtReynoldsNumber300IsBounded) {
  const ColumnFlow flow = plug_into_a_round_column(300, 1.5);
  EXPECT_NEAR(flow.inside + flow.outside, 1.0, 1e-3);
  EXPECT_LT(flow.outside, 0.05);
  EXPECT_LT(flow.held, 1e-3);
}

}  // namespace
}  // namespace cosim::fluid::program
