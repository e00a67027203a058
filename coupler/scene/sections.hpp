// Readers of the scene's larger sections, shared by loader.cpp and the files it delegates to.
// Each reads one mapping, validates it completely and finish()es it.
#pragma once

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "coupler/scene/reader.hpp"
#include "coupler/scene/scene.hpp"

namespace cosim::scene {

// The scene's bodies and the entries of `bodies` that generated some of them.
struct Bodies {
  std::vector<Body> bodies;
  std::vector<BodyGenerator> generators;
};

// `dir` is the scene's folder, against which mesh and pose files are resolved; `output` is
// the scene's output.file, which no entry may read from.
Bodies read_bodies(const std::vector<Reader>& items, const Domain& domain, const std::filesystem::path& dir,
                   const std::filesystem::path& output);
// `dir` is the scene's folder, against which hostfiles are resolved.
std::vector<Participant> read_participants(const Reader& r, const Coupling& coupling, const std::filesystem::path& dir);

// A box given by `min` and `max` (the domain, a generator's region), max > min on every axis.
Domain read_box(const Reader& r);

// What every body of an entry shares, all but its name and position: fixed, shape,
// material, orientation, velocity and angular_velocity.
Body read_common(const Reader& r, const std::filesystem::path& dir);

// The entry's `file` resolved against `dir`; it must exist.
std::filesystem::path existing_file(const Reader& r, const std::filesystem::path& dir);

// "(extent [..] .. [..]) is outside the domain [..] .. [..]" if some of a moving body `b`
// is outside `d`; for a fixed body, "lies wholly outside" if none of it is inside: a fixed
// body may reach out of the domain, cut by its walls or, where the fluid's immersed boundary
// holds it, wrapping round a periodic face.
std::optional<std::string> outside_domain(const Body& b, const Domain& d);

// Scales `q` to unit length, or says why not ("not a unit quaternion (norm 1.1)").
std::optional<std::string> make_unit(Quat& q);

// Touching the domain boundary is fine; floating point noise in the sum must not make it an error.
inline constexpr double domain_slack = 1e-12;

inline std::string text(const Vec3& v) { return fmt::format("[{:g}]", fmt::join(v, ", ")); }

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
