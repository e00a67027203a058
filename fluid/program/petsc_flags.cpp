#include "fluid/program/petsc_flags.hpp"

#include <petscsys.h>

#include <cctype>
#include <sstream>
#include <stdexcept>

#include "fluid/petsc_check.hpp"

namespace cosim::fluid::program {

PetscFlags parse_petsc_flags(const std::string& text) {
  PetscFlags flags;
  std::istringstream in(text);
  for (std::string word; in >> word;) {
    // "-1e-3" is a value; a flag starts with '-' and a letter.
    if (word.size() > 1 && word[0] == '-' && std::isalpha(static_cast<unsigned char>(word[1])))
      flags.push_back({word, ""});
    else if (flags.empty() || !flags.back().second.empty())
      throw std::invalid_argument("'" + word + "' is not a flag (-name) and follows no flag");
    else
      flags.back().second = word;
  }
  return flags;
}

void insert_petsc_flags(const PetscFlags& flags) {
  for (const auto& [name, value] : flags) {
    PetscBool set = PETSC_FALSE;
    COSIM_PETSC(PetscOptionsHasName(nullptr, nullptr, name.c_str(), &set));
    if (set) continue;
    COSIM_PETSC(PetscOptionsSetValue(nullptr, name.c_str(), value.empty() ? nullptr : value.c_str()));
    // PETSc starts its event log at initialisation when the command line asks for a
    // report; asked for here, later, the log starts now so PetscFinalize can write it.
    if (name == "-log_view") COSIM_PETSC(PetscLogDefaultBegin());
  }
}

}  // namespace cosim::fluid::program
