// ten Cate's tank seen from its settling sphere at E1's Reynolds number 1.5: the sphere held
// in a square duct 20/3 diameters wide whose walls slide past, against OpenFOAM's
// body-fitted solution of the same steady problem (bench/fluid_accuracy/openfoam_duct.py,
// converged over three mesh levels to F / (3 pi mu U d) = 1.425; bench/fluid_accuracy/README.md "ten
// Cate's tank seen from the sphere"). The case is in bench/fluid_accuracy/cases.hpp.
#include <gtest/gtest.h>

#include "bench/fluid_accuracy/cases.hpp"

namespace cosim::fluid {

using ibm::IbmOptions;

namespace {

constexpr double kOpenFoam = 1.425;

// Three cells per diameter keep the test short; the study's d/h 6 and 9 agree with OpenFOAM
// within 0.15 %, d/h 3 within 1.6 %. (From Re 1.5 to 1.4 the factor moves by 0.3 % only: the
// side walls' Stokes correction and the inertial one trade places, so the test checks the
// two together, not each.)
TEST(IbmSlidingDuct, SphereBetweenSlidingWallsHasOpenFoamsDrag) {
  const bench::DuctDrag r = bench::sphere_in_sliding_duct(IbmOptions{}, 3, 1.5);
  PetscPrintf(PETSC_COMM_WORLD,
              "sphere held in the sliding duct, d/h 3, Re 1.5: F/(3 pi mu U d) %.5f, OpenFOAM %.3f; "
              "%d steps, %.1f s\n",
              r.factor, kOpenFoam, r.steps, r.seconds);
  EXPECT_NEAR(r.factor / kOpenFoam, 1, 0.02);
}

}  // namespace
}  // namespace cosim::fluid
