// PETSc flags from the scene ("-pressure_pc_type hypre ..."), the same flags as on the
// command line, which wins where both set one.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace cosim::fluid::program {

using PetscFlags = std::vector<std::pair<std::string, std::string>>;  // name with '-', value or ""

// Throws std::invalid_argument for a value without a flag before it.
PetscFlags parse_petsc_flags(const std::string& text);

// Sets the flags the command line has not set. Call before the solvers are created.
void insert_petsc_flags(const PetscFlags& flags);

}  // namespace cosim::fluid::program
