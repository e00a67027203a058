// Run under mpirun -n 2: the same flow on all ranks (PETSC_COMM_WORLD) and on each rank
// alone (PETSC_COMM_SELF) must agree to solver tolerance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "flow_checks.hpp"

namespace cosim::fluid {
namespace {

void expect_same_on_one_and_two_ranks(const ViscosityModel& viscosity, const char* name) {
  PetscMPIInt size = 0;
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  ASSERT_EQ(size, 2) << "run this test with mpirun -n 2";
  const auto distributed = testing::mixed_boundary_flow(PETSC_COMM_WORLD, viscosity, 1.0);
  const auto serial = testing::mixed_boundary_flow(PETSC_COMM_SELF, viscosity, 1.0);
  const double difference = testing::max_difference(distributed, serial);
  double magnitude = 0;
  for (const auto& component : serial)
    for (double v : component) magnitude = std::max(magnitude, std::abs(v));
  PetscPrintf(PETSC_COMM_WORLD,
              "2 ranks vs 1 rank, %s (12 x 8 x 6, 20 steps): max |difference| = %.2e (max |u| = %.2f)\n",
              name, difference, magnitude);
  EXPECT_LT(difference, 1e-8);
}

TEST(TwoRanks, SameAnswerAsOneRank) {
  expect_same_on_one_and_two_ranks(ViscosityModel::newtonian(0.02), "Newtonian");
}

// The viscosity field is read across rank boundaries too.
TEST(TwoRanks, SameAnswerAsOneRankCarreau) {
  expect_same_on_one_and_two_ranks(ViscosityModel::carreau(0.05, 0.005, 1.0, 0.5), "Carreau");
}

}  // namespace
}  // namespace cosim::fluid
