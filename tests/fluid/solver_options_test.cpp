// The pressure solver's defaults give way to options (as from the command line, prefix
// `pressure_`): BoomerAMG and geometric multigrid on the DMDA hierarchy, chosen by their
// flags, give the same flow as the default transforms, and a wrong option is an error
// rather than ignored.
#include <gtest/gtest.h>

#include <stdexcept>

#include "tests/fluid/flow_checks.hpp"

namespace cosim::fluid {

using viscous::ViscosityModel;

namespace {

// Runs the mixed-boundary flow with extra options in a database of its own.
testing::GatheredVelocity with_options(const char* options) {
  PetscOptions scoped = nullptr;
  PetscOptionsCreate(&scoped);
  PetscOptionsInsertString(scoped, options);
  PetscOptionsPush(scoped);
  testing::GatheredVelocity u;
  try {
    u = testing::mixed_boundary_flow(PETSC_COMM_WORLD, ViscosityModel::newtonian(0.02), 1.0);
  } catch (...) {
    PetscOptionsPop();
    PetscOptionsDestroy(&scoped);
    throw;
  }
  PetscOptionsPop();
  PetscOptionsDestroy(&scoped);
  return u;
}

TEST(PressureSolverOptions, AlgebraicAndGeometricMultigridAgree) {
  const auto reference = with_options("");
  for (const char* options :
       {"-pressure_pc_type hypre", "-pressure_pc_type mg -pressure_pc_mg_levels 2 -pressure_pc_mg_galerkin pmat"}) {
    const double difference = testing::max_difference(reference, with_options(options));
    PetscPrintf(PETSC_COMM_WORLD, "%s against the transforms: max |difference| = %.2e\n", options, difference);
    EXPECT_LT(difference, 1e-8) << options;
  }
}

TEST(PressureSolverOptions, UnknownPreconditionerIsAnError) {
  PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);  // the exception carries the message
  EXPECT_THROW(with_options("-pressure_pc_type no_such_preconditioner"), std::runtime_error);
  PetscPopErrorHandler();
}

}  // namespace
}  // namespace cosim::fluid
