// Readers of the scene's larger sections, shared by loader.cpp and the files it delegates to.
// Each reads one mapping, validates it completely and finish()es it.
#pragma once

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <string_view>
#include <vector>

#include "coupler/scene/reader.hpp"
#include "coupler/scene/scene.hpp"

namespace cosim::scene {

// `dir` is the scene's folder, against which mesh files are resolved.
std::vector<Body> read_bodies(const std::vector<Reader>& items, const Domain& domain, const std::filesystem::path& dir);
// `dir` is the scene's folder, against which hostfiles are resolved.
std::vector<Participant> read_participants(const Reader& r, const Coupling& coupling, const std::filesystem::path& dir);

// Body and participant names end up in file names, HDF5 paths and ZeroMQ identities (the
// protocol header holds 31 bytes of name).
inline bool is_name(std::string_view s) {
  return !s.empty() && s.size() <= 31 &&
         std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isalnum(c) || c == '_' || c == '-'; });
}
inline constexpr const char* name_rule = "expected a name of 1 to 31 letters, digits, '_' and '-'";

// Whether `part` fits into `whole` a whole number of times, to 1e-9 relative: 0.1 into 1.0
// must pass although 1.0 / 0.1 is not exactly 10 in floating point.
inline bool whole_multiple(double whole, double part) {
  const double n = std::round(whole / part);
  return n >= 1 && std::abs(whole - n * part) <= 1e-9 * whole;
}

}  // namespace cosim::scene
