// A container holds the fluid: pressure-driven flow through a round pipe made by the
// immersed boundary on the Cartesian grid (bench/fluid_accuracy/round_pipe.hpp) against
// Poiseuille's profile. The concave slope of the markers' retraction was calibrated on this
// flow at D/h 20 with the axis at (0.37, 0.61) cell widths off the grid's lines; here the
// axis lies elsewhere (`fluid_accuracy --pipe` runs D/h 30 and 40 and every kernel).
#include <gtest/gtest.h>

#include <petscsys.h>

#include <cmath>

#include "bench/fluid_accuracy/round_pipe.hpp"

namespace cosim::fluid {

using ibm::DeltaKernel;

namespace {

// Guards against: a concave wall's markers retracted the wrong way (the profile's radius
// off by a tenth of a cell), the fluid outside the container leaking through its wall, and
// markers crowding where the period wraps round.
TEST(IbmContainer, PoiseuilleInARoundPipeWithinTwoPerCent) {
  for (const Eigen::Vector2d& offset : {Eigen::Vector2d(0, 0), Eigen::Vector2d(0.5, 0.21)}) {
    const bench::PipeFlow f = bench::round_pipe(20, offset, 8, DeltaKernel::roma3);
    PetscPrintf(PETSC_COMM_WORLD,
                "round pipe D/h 20, axis (%.2f, %.2f) h off the grid's lines: profile off by at most %.4f of u_max, "
                "flow rate %+.4f; %d steps, %.1f s\n",
                offset.x(), offset.y(), f.profile_error, f.flow_rate_error, f.steps, f.seconds);
    EXPECT_LT(f.profile_error, 0.02);
    EXPECT_LT(std::abs(f.flow_rate_error), 0.02);
  }
}

}  // namespace
}  // namespace cosim::fluid
