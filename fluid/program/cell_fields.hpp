// The flow as cell-centred fields for the run file: velocity (3 components, the mean of
// the two faces normal to each, exact for a linear profile on stretched axes too),
// pressure, and alpha (the bodies' volume fraction, the largest over the bodies).
#pragma once

#include "coupler/field/field_frame.hpp"
#include "fluid/bodies/body_treatment.hpp"
#include "fluid/navier_stokes/navier_stokes.hpp"

namespace cosim::fluid::program {

// Collective: every rank computes its own cells and rank 0 receives the whole grid in the
// frame's order (other ranks get the grid's nodes and no fields).
field::FieldFrame cell_fields(const fluid::navier_stokes::NavierStokes& flow,
                              const fluid::bodies::BodyTreatment& bodies);

}  // namespace cosim::fluid::program
