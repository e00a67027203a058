// The operators that never change for a Newtonian fluid without imposed faces are solved
// by shortcuts: the projection by FastPoisson's transforms, the viscous half-step by
// FastViscous's (or, on the Krylov path, from its stencil weights without a matrix). Each must give what the general
// path (the assembled operator, solved by a Krylov method to 1e-10) gives, on every kind of boundary, on stretched
// axes, periodic axes and a two-dimensional (one periodic cell) grid.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>

#include "fluid/bodies/imposed_faces.hpp"
#include "fluid/grid/local_velocity.hpp"
#include "fluid/pressure/fast_poisson.hpp"
#include "fluid/pressure/pressure_solver.hpp"
#include "fluid/viscous/fast_viscous.hpp"
#include "fluid/viscous/viscous_axis_basis.hpp"
#include "fluid/viscous/viscous_solver.hpp"

namespace cosim::fluid {

using bodies::ImposedFace;
using bodies::ImposedFaces;
using grid::Axis;
using grid::Boundary;
using grid::BoundaryConditions;
using grid::BoundaryKind;
using grid::for_each_index;
using grid::Grid;
using grid::Index;
using grid::LocalVelocity;
using grid::Point;
using grid::Side;
using pressure::FastPoisson;
using pressure::PressureSolver;
using viscous::FastViscous;
using viscous::UniformViscousWeights;
using viscous::ViscosityField;
using viscous::ViscosityModel;
using viscous::viscous_axis_basis;
using viscous::viscous_axis_matrix;
using viscous::ViscousAxisBasis;
using viscous::ViscousSolver;

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
    case BoundaryKind::outflow:
      return Boundary::outflow();
    case BoundaryKind::inflow:
      return Boundary::inflow([](const Point& x, double) { return Point{0.3, -0.2, 0.5 * x[0]}; });
    default:
      return Boundary::moving_wall({0.4, 0.1, -0.2});
  }
}

void apply(const Case& k, const Grid& grid, BoundaryConditions& bc) {
  for (int d = 0; d < 3; ++d)
    if (!grid.axis(d).periodic())
      for (Side s : {Side::lower, Side::upper})
        bc.set(d, s, boundary(k.kinds[static_cast<std::size_t>(d)][static_cast<std::size_t>(s)]));
}

std::vector<Case> cases() {
  using K = BoundaryKind;
  const auto wall = K::wall, out = K::outflow, in = K::inflow;
  return {
      {"closed box, stretched z",
       {Axis::uniform(12, 0, 1.2, false), Axis::uniform(10, 0, 1, false), Axis::stretched(9, 0, 1, 1.2, false)},
       {{{wall, wall}, {wall, wall}, {wall, wall}}}},
      {"periodic x, inflow to outflow along stretched z",
       {Axis::uniform(8, 0, 1, true), Axis::uniform(10, 0, 1, false), Axis::stretched(12, 0, 2, 0.8, false)},
       {{{wall, wall}, {wall, wall}, {in, out}}}},
      {"outflows along x, one wall and one outflow along y, periodic z",
       {Axis::uniform(9, 0, 1, false), Axis::uniform(7, 0, 1, false), Axis::uniform(10, 0, 1, true)},
       {{{out, out}, {wall, out}, {wall, wall}}}},
      {"outflow then wall along y, periodic stretched z",
       {Axis::uniform(6, 0, 1, false), Axis::uniform(8, 0, 1, false), Axis::stretched(10, 0, 1, 0.7, true)},
       {{{in, out}, {out, wall}, {wall, wall}}}},
      {"fully periodic, two cells along z",
       {Axis::uniform(8, 0, 1, true), Axis::uniform(6, 0, 1, true), Axis::uniform(2, 0, 1, true)},
       {{{wall, wall}, {wall, wall}, {wall, wall}}}},
      {"two-dimensional: one periodic cell along z (on two ranks one holds no plane)",
       {Axis::uniform(10, 0, 1, false), Axis::uniform(6, 0, 1, false), Axis::uniform(1, 0, 0.1, true)},
       {{{wall, out}, {in, wall}, {wall, wall}}}},
      {"two-dimensional: one periodic cell along y",
       {Axis::uniform(16, 0, 2, false), Axis::uniform(1, 0, 0.1, true), Axis::uniform(8, 0, 1, false)},
       {{{in, out}, {wall, wall}, {wall, wall}}}},
  };
}

// Calls f(case, grid, bc) for each of cases(), its boundary conditions applied.
template <typename F>
void for_each_case(F&& f) {
  for (const Case& k : cases()) {
    Grid grid(PETSC_COMM_WORLD, k.axes);
    BoundaryConditions bc(grid);
    apply(k, grid, bc);
    f(k, grid, bc);
  }
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
  Grid grid(PETSC_COMM_WORLD,
            {Axis::stretched(8, 0, 1, 1, false), Axis::uniform(8, 0, 1, false), Axis::uniform(8, 0, 1, false)});
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
    ViscousSolver assembled(grid, bc, nullptr);
    auto stencil_solver =
        with_options("-viscous_solver krylov", [&] { return std::make_unique<ViscousSolver>(grid, bc, &weights); });
    ViscousSolver& stencil = *stencil_solver;
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

// The bases FastViscous uses along x and y diagonalise the 1D operators the stencil applies:
// A B = B diag(lambda) and F B = I, for every component, axis and kind of end of cases().
TEST(ViscousAxisBasis, DiagonalisesTheStencilsOneDimensionalOperators) {
  const double nu = 0.05;
  for_each_case([&](const Case& k, const Grid& grid, const BoundaryConditions& bc) {
    const UniformViscousWeights weights(grid, bc, nu);
    for (int c = 0; c < 3; ++c)
      for (int d = 0; d < 2; ++d) {
        const ViscousAxisBasis b = viscous_axis_basis(grid, bc, weights, c, d);
        const std::vector<double> a = viscous_axis_matrix(grid, bc, weights, c, d);
        const PetscInt n = b.size;
        double scale = 0, residual = 0, identity = 0;
        for (double v : a) scale = std::max(scale, std::abs(v));
        const auto B = [&](PetscInt r, PetscInt q) { return b.backward[static_cast<std::size_t>(q * n + r)]; };
        const auto F = [&](PetscInt r, PetscInt q) { return b.forward[static_cast<std::size_t>(q * n + r)]; };
        for (PetscInt r = 0; r < n; ++r)
          for (PetscInt q = 0; q < n; ++q) {
            double ab = 0, fb = 0;
            for (PetscInt l = 0; l < n; ++l) {
              ab += a[static_cast<std::size_t>(r * n + l)] * B(l, q);
              fb += F(r, l) * B(l, q);
            }
            residual = std::max(residual, std::abs(ab - B(r, q) * b.eigenvalues[static_cast<std::size_t>(q)]));
            identity = std::max(identity, std::abs(fb - (r == q ? 1 : 0)));
          }
        EXPECT_LT(residual, 1e-12 * std::max(scale, 1.0)) << k.name << ", component " << c << ", axis " << d;
        EXPECT_LT(identity, 1e-11) << k.name << ", component " << c << ", axis " << d;
        for (double lambda : b.eigenvalues) EXPECT_LE(lambda, 1e-12 * scale) << k.name;
      }
  });
}

// Which ends have a closed-form transform, read off the stencil's weights on an axis of n
// uniform cells: lambda = -4 nu sin^2(theta_k / 2) / h^2 with the theta_k of the DST-I
// (normal component between walls), the DCT-II (between outflows, normal or tangential),
// an odd-length quarter wave (normal, outflow below and wall above) and the real Fourier
// transform (periodic); a tangential component next to a wall has the quadratic closure's
// row [-4 4/3], whose basis has no closed form.
TEST(ViscousAxisBasis, MatchesTheClosedFormsWhereTheyExist) {
  using K = BoundaryKind;
  const double nu = 0.05, h = 0.125;
  const int n = 8;
  const auto check = [&](bool periodic, K lower, K upper, int c, std::vector<double> theta) {
    Grid grid(PETSC_COMM_WORLD,
              {Axis::uniform(n, 0, n * h, periodic), Axis::uniform(4, 0, 1, false), Axis::uniform(4, 0, 1, false)});
    BoundaryConditions bc(grid);
    if (!periodic) {
      bc.set(0, Side::lower, boundary(lower));
      bc.set(0, Side::upper, boundary(upper));
    }
    const UniformViscousWeights weights(grid, bc, nu);
    std::vector<double> got = viscous_axis_basis(grid, bc, weights, c, 0).eigenvalues, want;
    for (double t : theta) want.push_back(-4 * nu * std::pow(std::sin(t / 2) / h, 2));
    std::sort(got.begin(), got.end());
    std::sort(want.begin(), want.end());
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t i = 0; i < got.size(); ++i) EXPECT_NEAR(got[i], want[i], 1e-11 * nu / (h * h)) << i;
  };
  const double pi = std::numbers::pi;
  std::vector<double> dst1, dct2_faces, quarter, dct2_cells, fourier;
  for (int k = 1; k < n; ++k) dst1.push_back(pi * k / n);
  for (int k = 0; k < n - 1; ++k) dct2_faces.push_back(pi * k / (n - 1));
  for (int k = 0; k < n - 1; ++k) quarter.push_back(pi * (k + 0.5) / (n - 0.5));
  for (int k = 0; k < n; ++k) dct2_cells.push_back(pi * k / n);
  for (int k = 0; k < n; ++k) fourier.push_back(2 * pi * k / n);
  check(false, K::wall, K::inflow, 0, dst1);
  check(false, K::outflow, K::outflow, 0, dct2_faces);
  check(false, K::outflow, K::wall, 0, quarter);
  check(false, K::outflow, K::outflow, 1, dct2_cells);
  check(true, K::wall, K::wall, 0, fourier);
  check(true, K::wall, K::wall, 1, fourier);

  Grid grid(PETSC_COMM_WORLD,
            {Axis::uniform(n, 0, n * h, false), Axis::uniform(4, 0, 1, false), Axis::uniform(4, 0, 1, false)});
  BoundaryConditions bc(grid);
  const UniformViscousWeights weights(grid, bc, nu);
  const std::vector<double> a = viscous_axis_matrix(grid, bc, weights, 1, 0);
  EXPECT_NEAR(a[0] * h * h / nu, -4, 1e-12);
  EXPECT_NEAR(a[1] * h * h / nu, 4.0 / 3, 1e-12);
  EXPECT_NEAR(a[n + 0] * h * h / nu, 1, 1e-12);
}

// The transforms against the Krylov path (GMRES to a tight tolerance) on every grid of
// cases(), each component, at nu s / h^2 = 0.1 and 4 for h the smallest cell width.
TEST(FastViscous, SolvesWhatTheKrylovPathSolves) {
  const double nu = 0.05;
  for_each_case([&](const Case& k, const Grid& grid, const BoundaryConditions& bc) {
    ASSERT_TRUE(FastViscous::applies(grid)) << k.name;
    ViscosityField viscosity(grid, ViscosityModel::newtonian(nu), 1.0);
    const UniformViscousWeights weights(grid, bc, nu);
    double h = 1e300;
    for (int d = 0; d < 3; ++d)
      if (!grid.axis(d).degenerate())
        for (int i = 0; i < grid.axis(d).cells(); ++i) h = std::min(h, grid.axis(d).width(i));
    auto fft = with_options("-viscous_solver fft", [&] { return std::make_unique<ViscousSolver>(grid, bc, &weights); });
    auto krylov = with_options("-viscous_solver krylov -viscous_ksp_rtol 1e-14 -viscous_ksp_gmres_restart 60",
                               [&] { return std::make_unique<ViscousSolver>(grid, bc, &weights); });
    for (const double number : {0.1, 4.0}) {
      const double s = number * h * h / nu;
      for (int c = 0; c < 3; ++c) {
        Vec rhs, a, b;
        DMCreateGlobalVector(grid.velocity_dm(c), &rhs);
        VecDuplicate(rhs, &a);
        VecDuplicate(rhs, &b);
        std::array<Vec, 3> all{};
        for (int q = 0; q < 3; ++q) DMCreateGlobalVector(grid.velocity_dm(q), &all[q]);
        fill(grid, all);
        VecCopy(all[c], rhs);
        VecSet(a, 0);
        VecSet(b, 0);
        const int its = fft->solve(c, s, viscosity, nullptr, rhs, a);
        const int krylov_its = krylov->solve(c, s, viscosity, nullptr, rhs, b);
        const double difference = max_abs_difference(a, b), scale = max_abs(b);
        PetscPrintf(PETSC_COMM_WORLD,
                    "%s, nu s / h^2 %.1f, component %d: max |u_fft - u_krylov| %.2e of %.2e (%d Krylov iterations)\n",
                    k.name.c_str(), number, c, difference, scale, krylov_its);
        EXPECT_EQ(its, 0);
        EXPECT_GT(scale, 1e-3);
        EXPECT_LT(difference, 1e-10 * scale) << k.name << ", component " << c << ", nu s / h^2 " << number;
        VecDestroy(&rhs);
        VecDestroy(&a);
        VecDestroy(&b);
        for (Vec& v : all) VecDestroy(&v);
      }
    }
  });
}

// The choice errs clearly: an unknown value, and fft where it does not apply (a stretched x,
// a varying viscosity); a -viscous_ksp_* flag chooses the Krylov path.
TEST(FastViscous, TheOptionErrsClearly) {
  const auto message = [](const char* options, auto&& make) -> std::string {
    try {
      with_options(options, make);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "";
  };
  Grid uniform_grid(PETSC_COMM_WORLD,
                    {Axis::uniform(6, 0, 1, false), Axis::uniform(6, 0, 1, false), Axis::uniform(6, 0, 1, false)});
  Grid stretched_grid(PETSC_COMM_WORLD, {Axis::stretched(6, 0, 1, 1, false), Axis::uniform(6, 0, 1, false),
                                         Axis::uniform(6, 0, 1, false)});
  BoundaryConditions uniform_bc(uniform_grid), stretched_bc(stretched_grid);
  const UniformViscousWeights uniform_weights(uniform_grid, uniform_bc, 0.1),
      stretched_weights(stretched_grid, stretched_bc, 0.1);
  const auto on = [](const Grid& g, const BoundaryConditions& b, const UniformViscousWeights* w) {
    return [&g, &b, w] { return std::make_unique<ViscousSolver>(g, b, w); };
  };
  const std::string unknown = message("-viscous_solver spectral", on(uniform_grid, uniform_bc, &uniform_weights));
  EXPECT_NE(unknown.find("-viscous_solver"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("spectral"), std::string::npos) << unknown;
  const std::string stretched = message("-viscous_solver fft", on(stretched_grid, stretched_bc, &stretched_weights));
  EXPECT_NE(stretched.find("-viscous_solver fft"), std::string::npos) << stretched;
  EXPECT_NE(stretched.find("uniform x and y"), std::string::npos) << stretched;
  const std::string varying = message("-viscous_solver fft", on(uniform_grid, uniform_bc, nullptr));
  EXPECT_NE(varying.find("-viscous_solver fft"), std::string::npos) << varying;
  EXPECT_NE(varying.find("viscosity"), std::string::npos) << varying;
  // Where fft does not apply the default is the Krylov path, and a KSP flag asks for it.
  EXPECT_EQ(message("", on(stretched_grid, stretched_bc, &stretched_weights)), "");
  ViscosityField viscosity(uniform_grid, ViscosityModel::newtonian(0.1), 1.0);
  Vec rhs, x;
  DMCreateGlobalVector(uniform_grid.velocity_dm(0), &rhs);
  VecDuplicate(rhs, &x);
  VecSet(rhs, 1);
  VecSet(x, 0);
  const auto iterations = [&](const char* options) {
    auto solver = with_options(options, on(uniform_grid, uniform_bc, &uniform_weights));
    VecSet(x, 0);  // not the previous solution, which a Krylov solver would start from
    return solver->solve(0, 0.01, viscosity, nullptr, rhs, x);
  };
  EXPECT_EQ(iterations(""), 0);
  EXPECT_GT(iterations("-viscous_ksp_type gmres"), 0);
  EXPECT_GT(iterations("-viscous_solver krylov"), 0);
  VecDestroy(&rhs);
  VecDestroy(&x);
}

}  // namespace
}  // namespace cosim::fluid
