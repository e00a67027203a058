#pragma once
// Molecular species for DSMC, read from a YAML species file (species.yaml next to this
// header holds Ar, N2 and He from Bird 1994, Appendix A).

#include "tracker/constants.hpp"

#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>

namespace cosim::tracker::dsmc {

using tracker::boltzmann;

struct Species {
  std::string name;
  double mass = 0;           // kg
  double diameter_vhs = 0;   // m, VHS reference diameter at T_ref
  double diameter_vss = 0;   // m, VSS reference diameter at T_ref
  double omega = 0;          // viscosity index: mu ~ T^omega (0.5 hard sphere, 1 Maxwell)
  double alpha = 1;          // VSS scattering exponent (1 is VHS, isotropic)
  double T_ref = 0;          // K
  double viscosity_ref = 0;  // Pa s at T_ref
  int rotational_dof = 0;    // stored; rotational energy exchange is not modelled yet
};

// A species file that cannot be used: the message names the file, the line, the key and
// the value (what() is "file:line: key 'species.Ar.omega' = '-1': must lie in [0.5, 1]").
class SpeciesError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class SpeciesTable {
 public:
  // Throws SpeciesError naming the file and the species if it is not in the table.
  const Species& at(const std::string& name) const&;
  // On a temporary table (read_species(f).at("Ar")) a copy: a reference would dangle.
  Species at(const std::string& name) && { return static_cast<const SpeciesTable&>(*this).at(name); }
  bool contains(const std::string& name) const { return species_.contains(name); }
  const std::map<std::string, Species>& all() const { return species_; }
  const std::filesystem::path& file() const { return file_; }

 private:
  friend SpeciesTable read_species(const std::filesystem::path& file);
  std::filesystem::path file_;
  std::map<std::string, Species> species_;
};

// Reads and checks a species file: a top-level map `species:` of name -> {mass,
// diameter_vhs, diameter_vss, omega, alpha, T_ref, viscosity_ref, rotational_dof}, all
// required. Unknown keys, missing keys, non-numbers and values out of range are errors.
SpeciesTable read_species(const std::filesystem::path& file);

// The species file of the source tree (set by CMake).
std::filesystem::path default_species_file();

}  // namespace cosim::tracker::dsmc
