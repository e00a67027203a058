// The operators that never change for a Newtonian fluid without imposed faces are solved
// by shortcuts: the projection by FastPoisson's transforms, the viscous half-step from its
// stencil weights without a matrix. Each must give what the general path (the assembled
// operator, solved by a Krylov method to 1e-10) gives, on every kind of boundary, on
// stretched axes, periodic axes and a two-dimensional (one periodic cell) grid.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "fluid/fast_poisson.hpp"
#include "fluid/imposed_faces.hpp"
#include "fluid/local_velocity.hpp"
#include "fluid/pressure_solver.hpp"
#include "fluid/viscous_solver.hpp"

namespace cosim::fluid {
namespace {

// Runs f with extra PETSc options in a database of its own.
template <typename F>
auto with_options(const char* options, F&& f) {
  PetscOptions scoped = nullptr;
  PetscOptionsCreate(&scoped);
  PetscOptionsInsertString(scoped, options);
  PetscOptionsPush(scoped);
  struct Pop {
    PetscOptions o;
    ~Pop() {
      PetscOptionsPop();
      PetscOptionsDestroy(&o);
    }
  } pop{scoped};
  return f();
}

struct Case {
  std::string name;
  std::array<Axis, 3> axes;
  std::array<std::array<BoundaryKind, 2>, 3> kinds;  // non-periodic axes: wall, inflow or outflow
};

Boundary boundary(BoundaryKind kind) {
  switch (kind) {
    case BoundaryKind::outflow: return Boundary::outflow();
    case BoundaryKind::inflow: return Boundary::inflow([](const Point& x, double) { return Point{0.3, -0.2, 0.5 * x[0]}; });
    default: return Boundary::moving_wall({0.4, 0.1, -0.2});
  }
}

void apply(const Case& k, const Grid& grid, BoundaryConditions& bc) {
  for (int d = 0; d < 3; ++d)
    if (!grid.axis(d).periodic())
      for (Side s : {Side::lower, Side::upper}) bc.set(d, s, boundary(k.kinds[static_cast<std::size_t>(d)][static_cast<std::size_t>(s)]));
}

std::vector<Case> cases() {
  using K = BoundaryKind;
  const auto wall = K::wall, out = K::outflow, in = K::inflow;
  return {
      {"closed box, stretched z", {Axis::uniform(12, 0, 1.2, false), Axis::uniform(10, 0, 1, false), Axis::stretched(9, 0, 1, 1.2, false)},
       {{{wall, wall}, {wall, wall}, {wall, wall}}}},
      {"periodic x, inflow to outflow along stretched z", {Axis::uniform(8, 0, 1, true), Axis::uniform(10, 0, 1, false), Axis::stretched(12, 0, 2, 0.8, false)},
       {{{wall, wall}, {wall, wall}, {in, out}}}},
      {"outflows along x, one wall and one outflow along y, periodic z", {Axis::uniform(9, 0, 1, false), Axis::uniform(7, 0, 1, false), Axis::uniform(10, 0, 1, true)},
       {{{out, out}, {wall, out}, {wall, wall}}}},
      {"outflow then wall along y, periodic stretched z", {Axis::uniform(6, 0, 1, false), Axis::uniform(8, 0, 1, false), Axis::stretched(10, 0, 1, 0.7, true)},
       {{{in, out}, {out, wall}, {wall, wall}}}},
      {"fully periodic, two cells along z", {Axis::uniform(8, 0, 1, true), Axis::uniform(6, 0, 1, true), Axis::uniform(2, 0, 1, true)},
       {{{wall, wall}, {wall, wall}, {wall, wall}}}},
      {"two-dimensional: one periodic cell along z (on two ranks one holds no plane)", {Axis::uniform(10, 0, 1, false), Axis::uniform(6, 0, 1, false), Axis::uniform(1, 0, 0.1, true)},
       {{{wall, out}, {in, wall}, {wall, wall}}}},
      {"two-dimensional: one periodic cell along y", {Axis::uniform(16, 0, 2, false), Axis::uniform(1, 0, 0.1, true), Axis::uniform(8, 0, 1, false)},
       {{{in, out}, {wall, wall}, {wall, wall}}}},
  };
}

// A velocity with divergence everywhere, boundary values as the conditions impose.
void fill(const Grid& grid, const std::array<Vec, 3>& u) {
  for (int c = 0; c < 3; ++c) {
    DM dm = grid.velocity_dm(c);
    PetscScalar*** a = nullptr;
    DMDAVecGetArray(dm, u[c], &a);
    for_each_index(grid.owned(dm), [&](const Index& p) {
      const Point x = grid.position(c, p);
      a[p[2]][p[1]][p[0]] = std::sin(3 * x[0] + c) * std::cos(2 * x[1] - 1) + x[2] * x[2] * (c + 1) + 0.1 * c;
    });
    DMDAVecRestoreArray(dm, u[c], &a);
  }
}

double max_abs_difference(Vec a, Vec b) {
  Vec d;
  VecDuplicate(a, &d);
  VecWAXPY(d, -1, a, b);
  double norm = 0;
  VecNorm(d, NORM_INFINITY, &norm);
  VecDestroy(&d);
  return norm;
}

double max_abs(Vec a) {
  double norm = 0;
  VecNorm(a, NORM_INFINITY, &norm);
  return norm;
}

TEST(FastPoisson, SolvesTheAssembledProjectionOnEveryKindOfBoundary) {
  for (const Case& k : cases()) {
    Grid grid(PETSC_COMM_WORLD, k.axes);
    BoundaryConditions bc(grid);
    apply(k, grid, bc);
    ASSERT_TRUE(FastPoisson::applies(grid)) << k.name;
    std::array<Vec, 3> u{};
    for (int c = 0; c < 3; ++c) DMCreateGlobalVector(grid.velocity_dm(c), &u[c]);
    fill(grid, u);
    LocalVelocity local(grid);
    local.update(u, bc, 0);
    Vec fft, krylov;
    DMCreateGlobalVector(grid.pressure_dm(), &fft);
    DMCreateGlobalVector(grid.pressure_dm(), &krylov);
    const int iterations = with_options("-pressure_solver fft", [&] {
      PressureSolver solver(grid, bc);
      return solver.solve(local, 0.1, nullptr, fft);
    });
    with_options("-pressure_solver krylov -pressure_ksp_rtol 1e-13", [&] {
      PressureSolver solver(grid, bc);
      return solver.solve(local, 0.1, nullptr, krylov);
    });
    const double difference = max_abs_difference(fft, krylov), scale = max_abs(krylov);
    PetscPrintf(PETSC_COMM_WORLD, "%s: max |phi_fft - phi_krylov| = %.2e of max |phi| %.2e\n", k.name.c_str(),
                difference, scale);
    EXPECT_EQ(iterations, 0) << k.name;
    EXPECT_GT(scale, 1e-3) << k.name;
    EXPECT_LT(difference, 1e-9 * scale) << k.name;
    VecDestroy(&fft);
    VecDestroy(&krylov);
    for (Vec& v : u) VecDestroy(&v);
  }
}

TEST(FastPoisson, NeedsUniformXAndY) {
  Grid grid(PETSC_COMM_WORLD, {Axis::stretched(8, 0, 1, 1, false), Axis::uniform(8, 0, 1, false),
                               Axis::uniform(8, 0, 1, false)});
  BoundaryConditions bc(grid);
  EXPECT_FALSE(FastPoisson::applies(grid));
  EXPECT_THROW(with_options("-pressure_solver fft", [&] { return PressureSolver(grid, bc).assemblies(); }),
               std::invalid_argument);
  EXPECT_THROW(with_options("-pressure_solver spectral", [&] { return PressureSolver(grid, bc).assemblies(); }),
               std::invalid_argument);
  // The Krylov solver takes the stretched grid.
  EXPECT_EQ(with_options("", [&] { return PressureSolver(grid, bc).assemblies(); }), 0);
}

// Both viscous operators on the same right-hand side: the stencil's without a matrix and
// the assembled one, with and without imposed faces.
TEST(ViscousSolver, TheStencilOperatorSolvesWhatTheAssembledOneDoes) {
  const double nu = 0.05, s = 0.02;
  for (const Case& k : cases()) {
    Grid grid(PETSC_COMM_WORLD, k.axes);
    BoundaryConditions bc(grid);
    apply(k, grid, bc);
    ViscosityField viscosity(grid, ViscosityModel::newtonian(nu), 1.0);
    const UniformViscousWeights weights(grid, bc, nu);
    ViscousSolver stencil(grid, bc, &weights), assembled(grid, bc, nullptr);
    ImposedFaces imposed(grid);
    imposed.clear();
    for (int c = 0; c < 3; ++c)
      for_each_index(grid.owned(grid.velocity_dm(c)), [&](const Index& p) {
        if (p[0] == 2 && p[2] == 1 && !grid.on_boundary(c, p)) imposed.add(c, p, 0.7);
      });
    imposed.finish();
    for (const ImposedFaces* faces : std::array<const ImposedFaces*, 2>{nullptr, &imposed}) {
      std::array<Vec, 3> rhs{}, a{}, b{};
      for (int c = 0; c < 3; ++c) {
        DMCreateGlobalVector(grid.velocity_dm(c), &rhs[c]);
        VecDuplicate(rhs[c], &a[c]);
        VecDuplicate(rhs[c], &b[c]);
      }
      fill(grid, rhs);
      for (int c = 0; c < 3; ++c) {
        if (faces) {
          PetscScalar*** r = nullptr;
          DMDAVecGetArray(grid.velocity_dm(c), rhs[c], &r);
          for (const ImposedFace& f : faces->owned(c)) r[f.at[2]][f.at[1]][f.at[0]] = f.value;
          DMDAVecRestoreArray(grid.velocity_dm(c), rhs[c], &r);
        }
        VecSet(a[c], 0);
        VecSet(b[c], 0);
        const int its = stencil.solve(c, s, viscosity, faces, rhs[c], a[c]);
        assembled.solve(c, s, viscosity, faces, rhs[c], b[c]);
        const double difference = max_abs_difference(a[c], b[c]), scale = max_abs(b[c]);
        PetscPrintf(PETSC_COMM_WORLD, "%s, component %d%s: %d iterations, max difference %.2e of %.2e\n",
                    k.name.c_str(), c, faces ? ", imposed faces" : "", its, difference, scale);
        EXPECT_LT(difference, 1e-8 * scale) << k.name << ", component " << c;
      }
      for (auto* vs : {&rhs, &a, &b})
        for (Vec& v : *vs) VecDestroy(&v);
    }
  }
}

}  // namespace
}  // namespace cosim::fluid
