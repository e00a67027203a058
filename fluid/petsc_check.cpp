#include "fluid/petsc_check.hpp"

#include <stdexcept>
#include <string>

namespace cosim::fluid {

void petsc_check(PetscErrorCode code, const char* file, int line) {
  if (code == 0) return;
  const char* text = nullptr;
  char* detail = nullptr;
  PetscErrorMessage(code, &text, &detail);
  throw std::runtime_error(std::string("PETSc error ") + std::to_string(code) + " (" + (text ? text : "unknown") +
                           (detail && *detail ? std::string(": ") + detail : std::string()) + ") at " + file + ":" +
                           std::to_string(line));
}

int solve_or_throw(KSP ksp, Vec b, Vec x, const std::string& what) {
  COSIM_PETSC(KSPSolve(ksp, b, x));
  KSPConvergedReason reason;
  COSIM_PETSC(KSPGetConvergedReason(ksp, &reason));
  if (reason < 0) throw std::runtime_error(what + " did not converge: " + KSPConvergedReasons[reason]);
  PetscInt iterations = 0;
  COSIM_PETSC(KSPGetIterationNumber(ksp, &iterations));
  return static_cast<int>(iterations);
}

}  // namespace cosim::fluid
