#pragma once
// PETSc reports errors through return codes; the fluid library's C++ interface reports
// them as exceptions so callers (tests, the program, later the coupler adapter) can name
// the failing step. PETSc callbacks keep using PetscCall.
#include <petscksp.h>

#include <string>

namespace cosim::fluid {

// Throws std::runtime_error carrying PETSc's message and the call site when code != 0.
void petsc_check(PetscErrorCode code, const char* file, int line);

// Runs create(), and release() if it throws: a constructor that throws gets no destructor
// call, so whatever PETSc objects it made would leak.
template <typename Create, typename Release>
void create_or_release(Create&& create, Release&& release) {
  try {
    create();
  } catch (...) {
    release();
    throw;
  }
}

// KSPSolve that throws, naming `what`, when the solver diverged; returns the iterations.
int solve_or_throw(KSP ksp, Vec b, Vec x, const std::string& what);

}  // namespace cosim::fluid

#define COSIM_PETSC(...) ::cosim::fluid::petsc_check((__VA_ARGS__), __FILE__, __LINE__)
