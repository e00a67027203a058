// Grid geometry and the checks on boundary conditions.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "fluid/navier_stokes/navier_stokes.hpp"

namespace cosim::fluid {

using grid::Axis;
using grid::Boundary;
using grid::BoundaryConditions;
using grid::Grid;
using grid::Point;
using grid::Side;
using navier_stokes::NavierStokes;

namespace {

TEST(Axis, StretchedClustersAtBothEndsAndKeepsTheEnds) {
  const Axis a = Axis::stretched(16, -1, 3, 1.5, false);
  EXPECT_DOUBLE_EQ(a.lo(), -1);
  EXPECT_DOUBLE_EQ(a.hi(), 3);
  EXPECT_LT(a.width(0), 0.5 * a.width(8));
  EXPECT_NEAR(a.width(0), a.width(15), 1e-12);
}

TEST(Axis, GhostFacesMirrorOrRepeat) {
  const Axis bounded = Axis::from_faces({0, 1, 3, 6}, false);
  EXPECT_DOUBLE_EQ(bounded.face(-1), -1);
  EXPECT_DOUBLE_EQ(bounded.face(4), 9);
  EXPECT_DOUBLE_EQ(bounded.centre(-1), -0.5);  // the mirror image of the first centre
  const Axis periodic = Axis::from_faces({0, 1, 3, 6}, true);
  EXPECT_DOUBLE_EQ(periodic.face(-1), 3 - 6);
  EXPECT_DOUBLE_EQ(periodic.face(5), 3 + 6);
  const Axis layer = Axis::uniform(1, 0, 2, true);
  EXPECT_TRUE(layer.degenerate());
  EXPECT_DOUBLE_EQ(layer.face(-2), -4);
  EXPECT_DOUBLE_EQ(layer.face(3), 6);
}

TEST(Axis, RejectsBadFaces) {
  EXPECT_THROW(Axis::from_faces({0, 1, 1, 2}, false), std::invalid_argument);
  EXPECT_THROW(Axis::uniform(1, 0, 1, false), std::invalid_argument);
  EXPECT_THROW(Axis::stretched(4, 0, 1, -1, false), std::invalid_argument);
}

TEST(BoundaryConditions, RejectsInconsistentFaces) {
  Grid grid(PETSC_COMM_WORLD,
            {Axis::uniform(4, 0, 1, false), Axis::uniform(4, 0, 1, true), Axis::uniform(1, 0, 1, true)});
  BoundaryConditions bc(grid);
  EXPECT_THROW(bc.set(0, Side::lower, Boundary::periodic()), std::invalid_argument);
  EXPECT_THROW(bc.set(1, Side::lower, Boundary::no_slip()), std::invalid_argument);
  bc.set(0, Side::lower, Boundary::inflow([](const Point&, double) { return Point{1, 0, 0}; }));
  EXPECT_THROW(NavierStokes(grid, bc, {}, {}), std::invalid_argument);
  bc.set(0, Side::upper, Boundary::outflow());
  EXPECT_NO_THROW(NavierStokes(grid, bc, {}, {}));
}

TEST(BoundaryConditions, WallsKeepOnlyTheirTangentialVelocity) {
  Grid grid(PETSC_COMM_WORLD,
            {Axis::uniform(4, 0, 1, false), Axis::uniform(4, 0, 1, false), Axis::uniform(1, 0, 1, true)});
  BoundaryConditions bc(grid);
  bc.set(1, Side::upper, Boundary::moving_wall({1, 2, 3}));
  const Point u = bc.velocity(1, Side::upper, {0.5, 1, 0.5}, 0);
  EXPECT_EQ(u[0], 1);
  EXPECT_EQ(u[1], 0);
  EXPECT_EQ(u[2], 3);
}

}  // namespace
}  // namespace cosim::fluid
