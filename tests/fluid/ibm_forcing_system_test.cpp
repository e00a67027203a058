// The immersed boundary's forcing system assembled from the markers' kernels: its product
// is interpolating what is spread through the grid, also where the markers spread from
// elsewhere than they interpolate (a moving body's, unsymmetric), and its solve meets the
// markers' velocities to the tolerance, one iteration for one body with each body solved
// exactly, and a body's block is factored again only when it changes, numerically only
// where its pattern stays.
#include <gtest/gtest.h>
#include <petscdmda.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <random>
#include <utility>

#include "fluid/ibm/forcing_system.hpp"
#include "fluid/ibm/marker_stencils.hpp"
#include "fluid/petsc_check.hpp"

namespace cosim::fluid {

using grid::Axis;
using grid::Box;
using grid::Grid;
using ibm::ActiveMarker;
using ibm::BodyBlockSolvers;
using ibm::DeltaKernel;
using ibm::FaceArrays;
using ibm::ForcingSystem;
using ibm::kernel_stencil;
using ibm::MarkerStencils;
using ibm::roots_by_body;

namespace {

// Markers about a cell apart on two spheres whose kernels overlap, on a grid with walls, a
// stretched axis and a periodic one: body 0's markers first, then body 1's, all moved by
// `shift` and body 1's also by `second`.
struct Cloud {
  Grid grid{
      PETSC_COMM_SELF,
      {Axis::uniform(16, 0, 1.6, false), Axis::stretched(14, 0, 1.4, 0.8, false), Axis::uniform(12, 0, 1.2, true)}};
  std::vector<ActiveMarker> markers;
  std::vector<std::size_t> first_marker{0};

  explicit Cloud(const Eigen::Vector3d& shift = Eigen::Vector3d::Zero(),
                 const Eigen::Vector3d& second = Eigen::Vector3d::Zero()) {
    const Eigen::Vector3d centres[] = {Eigen::Vector3d(0.62, 0.71, 0.55) + shift,
                                       Eigen::Vector3d(1.0, 0.69, 0.61) + shift + second};
    std::array<Box, 3> owned;
    for (int c = 0; c < 3; ++c) owned[static_cast<std::size_t>(c)] = grid.owned(grid.velocity_dm(c));
    for (const Eigen::Vector3d& centre : centres) {
      const int count = 28;
      for (int k = 0; k < count; ++k) {
        // A Fibonacci sphere of radius 0.15: its markers about a cell (0.1) apart.
        const double z = 1 - (2 * k + 1.0) / count, r = std::sqrt(1 - z * z);
        const double angle = k * std::numbers::pi * (3 - std::sqrt(5.0));
        ActiveMarker a;
        a.body = first_marker.size() - 1;
        a.marker = static_cast<std::size_t>(k);
        a.id = markers.size();
        a.position = centre + 0.15 * Eigen::Vector3d(r * std::cos(angle), r * std::sin(angle), z);
        a.volume = 1e-3;
        for (std::size_t c = 0; c < 3; ++c) {
          a.stencil[c] = kernel_stencil(grid, static_cast<int>(c), DeltaKernel::roma3,
                                        {a.position[0], a.position[1], a.position[2]});
          a.local[c] = a.stencil[c].meets(owned[c]);
        }
        markers.push_back(a);
      }
      first_marker.push_back(markers.size());
    }
  }
};

// The three velocity components' owned arrays, zero.
struct Fields {
  const Grid& grid;
  std::array<Vec, 3> v{};
  FaceArrays a{};
  explicit Fields(const Grid& g) : grid(g) {
    for (int c = 0; c < 3; ++c) {
      COSIM_PETSC(DMCreateGlobalVector(grid.velocity_dm(c), &v[static_cast<std::size_t>(c)]));
      COSIM_PETSC(
          DMDAVecGetArray(grid.velocity_dm(c), v[static_cast<std::size_t>(c)], &a[static_cast<std::size_t>(c)]));
    }
  }
  ~Fields() {
    for (int c = 0; c < 3; ++c) {
      DMDAVecRestoreArray(grid.velocity_dm(c), v[static_cast<std::size_t>(c)], &a[static_cast<std::size_t>(c)]);
      VecDestroy(&v[static_cast<std::size_t>(c)]);
    }
  }
};

std::vector<double> random_values(std::size_t n) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<double> out(n);
  for (double& x : out) x = u(random);
  return out;
}

// Where a moving body's markers spread from: a third of a cell back along each axis.
const Eigen::Vector3d kEarlier(-0.031, 0.027, -0.034);

void expect_product_is_interpolating_what_is_spread(const Eigen::Vector3d& earlier) {
  Cloud cloud, spreading_cloud(earlier);
  const PetscInt roots = roots_by_body(PETSC_COMM_SELF, cloud.first_marker);
  const MarkerStencils stencils(cloud.grid, cloud.markers, roots);
  const MarkerStencils spreading(cloud.grid, spreading_cloud.markers, roots);
  const std::size_t n = 3 * cloud.markers.size();
  const std::vector<double> g = random_values(n);
  std::vector<double> through_grid(n);
  {
    Fields f(cloud.grid);
    spreading.spread(f.a, g);
    stencils.interpolate(f.a, through_grid);
  }
  std::vector<double> assembled(n, 0.0);
  bool coupled = false;  // the two bodies' kernels overlap
  for (const MarkerStencils::Product& p : stencils.products(spreading)) {
    assembled[static_cast<std::size_t>(p.row)] += p.value * g[static_cast<std::size_t>(p.column)];
    EXPECT_EQ(p.row % 3, p.column % 3);
    coupled = coupled || (p.row < 84) != (p.column < 84);
  }
  EXPECT_TRUE(coupled);
  double largest = 0, scale = 0;
  for (std::size_t i = 0; i < n; ++i) {
    largest = std::max(largest, std::abs(assembled[i] - through_grid[i]));
    scale = std::max(scale, std::abs(through_grid[i]));
  }
  EXPECT_LT(largest, 1e-13 * scale) << "scale " << scale;
}

TEST(IbmForcingSystem, ProductIsInterpolatingWhatIsSpread) {
  expect_product_is_interpolating_what_is_spread(Eigen::Vector3d::Zero());
}

TEST(IbmForcingSystem, ProductIsInterpolatingWhatIsSpreadFromElsewhere) {
  expect_product_is_interpolating_what_is_spread(kEarlier);
}

void expect_solve_meets_the_tolerance(const Eigen::Vector3d& earlier) {
  Cloud cloud, spreading_cloud(earlier);
  const PetscInt roots = roots_by_body(PETSC_COMM_SELF, cloud.first_marker);
  const MarkerStencils stencils(cloud.grid, cloud.markers, roots);
  const MarkerStencils spreading(cloud.grid, spreading_cloud.markers, roots);
  BodyBlockSolvers blocks;
  const ForcingSystem system(stencils, earlier.isZero() ? stencils : spreading, cloud.first_marker, blocks);
  const std::size_t n = 3 * cloud.markers.size();
  // The misses of two bodies moving against each other, rotating.
  std::vector<double> r(n);
  for (const ActiveMarker& m : cloud.markers) {
    const Eigen::Vector3d u = Eigen::Vector3d(m.body == 0 ? 1 : -1, 0.3, -0.2) +
                              Eigen::Vector3d(0, 0, 2).cross(m.position - Eigen::Vector3d(0.8, 0.7, 0.6));
    for (std::size_t c = 0; c < 3; ++c) r[3 * m.id + c] = u[static_cast<Eigen::Index>(c)];
  }
  std::vector<double> g(n, 0.0), residual = r;
  const int iterations = system.solve(g, residual, 1e-10, 200);
  EXPECT_GT(iterations, 1);
  EXPECT_LT(iterations, 60);
  // What is left, checked through the grid.
  std::vector<double> image(n);
  {
    Fields f(cloud.grid);
    (earlier.isZero() ? stencils : spreading).spread(f.a, g);
    stencils.interpolate(f.a, image);
  }
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_NEAR(r[i] - image[i], residual[i], 1e-12);
    EXPECT_LE(std::abs(residual[i]), 1e-10);
  }
}

TEST(IbmForcingSystem, SolveMeetsTheTolerance) { expect_solve_meets_the_tolerance(Eigen::Vector3d::Zero()); }

TEST(IbmForcingSystem, SolveMeetsTheToleranceSpreadingFromElsewhere) { expect_solve_meets_the_tolerance(kEarlier); }

// By the default factors (Cholesky) and by PETSc's LU chosen through the options.
TEST(IbmForcingSystem, ABodyAloneSolvedExactlyTakesOneIteration) {
  Cloud cloud;
  cloud.markers.resize(cloud.first_marker[1]);
  cloud.first_marker.pop_back();
  for (const char* factor : {"", "lu"}) {
    if (*factor != 0) COSIM_PETSC(PetscOptionsSetValue(nullptr, "-ibm_forcing_sub_pc_type", factor));
    const MarkerStencils stencils(cloud.grid, cloud.markers, roots_by_body(PETSC_COMM_SELF, cloud.first_marker));
    BodyBlockSolvers blocks;
    const ForcingSystem system(stencils, stencils, cloud.first_marker, blocks);
    COSIM_PETSC(PetscOptionsClearValue(nullptr, "-ibm_forcing_sub_pc_type"));
    const std::size_t n = 3 * cloud.markers.size();
    std::vector<double> g(n, 0.0), residual = random_values(n);
    EXPECT_EQ(system.solve(g, residual, 1e-10, 200), 1) << factor;
    for (double x : residual) EXPECT_LE(std::abs(x), 1e-10) << factor;
  }
}

// The solution of a random right-hand side and the iterations it took.
std::pair<int, std::vector<double>> solved(const Cloud& cloud, BodyBlockSolvers& blocks) {
  const MarkerStencils stencils(cloud.grid, cloud.markers, roots_by_body(PETSC_COMM_SELF, cloud.first_marker));
  const ForcingSystem system(stencils, stencils, cloud.first_marker, blocks);
  const std::size_t n = 3 * cloud.markers.size();
  std::vector<double> g(n, 0.0), residual = random_values(n);
  const int iterations = system.solve(g, residual, 1e-10, 200);
  return {iterations, g};
}

TEST(IbmForcingSystem, ABodysBlockIsFactoredOnceWhileItStaysTheSame) {
  const Cloud cloud, moved(Eigen::Vector3d::Zero(), Eigen::Vector3d(0.013, -0.007, 0.004));
  BodyBlockSolvers blocks;
  const auto first = solved(cloud, blocks);
  EXPECT_EQ(blocks.factorizations(), 2);
  // Neither body moved: the same factors give the same solution.
  EXPECT_EQ(solved(cloud, blocks), first);
  EXPECT_EQ(blocks.factorizations(), 2);
  // Body 1 moved: its block alone is factored again, and the solution is a fresh solver's.
  const auto after = solved(moved, blocks);
  EXPECT_EQ(blocks.factorizations(), 3);
  EXPECT_EQ(blocks.refactorizations(), 0);
  BodyBlockSolvers fresh;
  EXPECT_EQ(solved(moved, fresh), after);
  EXPECT_NE(after.second, first.second);
  // Body 1 moved by a hair: new values on the same pattern, factored numerically only, and
  // the solution is a fresh solver's.
  const Cloud nudged(Eigen::Vector3d::Zero(), Eigen::Vector3d(0.013, -0.007, 0.004 + 1e-6));
  const auto nudged_solution = solved(nudged, blocks);
  EXPECT_EQ(blocks.factorizations(), 3);
  EXPECT_EQ(blocks.refactorizations(), 1);
  BodyBlockSolvers fresh_again;
  const auto expected = solved(nudged, fresh_again);
  EXPECT_EQ(nudged_solution.first, expected.first);
  for (std::size_t i = 0; i < expected.second.size(); ++i)
    EXPECT_NEAR(nudged_solution.second[i], expected.second[i], 1e-12 * std::abs(expected.second[i]) + 1e-15);
  EXPECT_NE(nudged_solution.second, after.second);
}

}  // namespace
}  // namespace cosim::fluid
