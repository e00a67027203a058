#pragma once
// A parallel sparse matrix from entries that several ranks give for one row (the forcing's
// B, whose row of a marker on a cut between ranks is summed from each rank's faces): the
// entries sent to the rows' owners, summed there and laid out row by row. Where the entries
// come grouped by row in ascending order, each row's columns ascending, as
// MarkerStencils::products gives them, nothing is sorted but the few rows that arrive from
// more than one rank, where PETSc's COO assembly sorts them all.
#include <petscmat.h>

#include <vector>

#include "fluid/ibm/marker_stencils.hpp"

namespace cosim::fluid::ibm {

// The matrix of `rows` rows on this rank (the next range of global numbers after the lower
// ranks'), square, holding the sum of the entries every rank gives; every row holds its
// diagonal, 1 where nothing else is on it (a row no rank gives entries for). Collective.
Mat summed_rows(MPI_Comm comm, PetscInt rows, std::vector<MarkerStencils::Product> entries);

}  // namespace cosim::fluid::ibm
