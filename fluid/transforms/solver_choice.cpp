#include "fluid/transforms/solver_choice.hpp"

#include <petscsys.h>

#include <stdexcept>

#include "fluid/petsc_check.hpp"

namespace cosim::fluid::transforms {

bool use_transforms(const std::string& prefix, const std::string& obstacle) {
  const std::string option = "-" + prefix + "_solver";
  char name[16] = "";
  PetscBool set = PETSC_FALSE;
  COSIM_PETSC(PetscOptionsGetString(nullptr, nullptr, option.c_str(), name, sizeof name, &set));
  const std::string chosen = set ? name : "";
  if (set && chosen != "fft" && chosen != "krylov")
    throw std::invalid_argument(option + ": '" + chosen + "' is neither fft nor krylov");
  if (chosen == "fft" && !obstacle.empty()) throw std::invalid_argument(option + " fft: " + obstacle);
  if (set) return chosen == "fft";
  char* all = nullptr;
  COSIM_PETSC(PetscOptionsGetAll(nullptr, &all));
  const std::string options = all ? all : "";
  COSIM_PETSC(PetscFree(all));
  const bool krylov_flags = options.find("-" + prefix + "_ksp_") != std::string::npos ||
                            options.find("-" + prefix + "_pc_") != std::string::npos;
  return !krylov_flags && obstacle.empty();
}

}  // namespace cosim::fluid::transforms
