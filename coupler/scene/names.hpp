// The words the scene file uses for each enum, indexed by the enum's value. One table serves
// both reading (Reader::choice) and writing (to_string), so the two cannot drift apart.
#pragma once

#include <array>
#include <string>

#include "coupler/scene/reader.hpp"
#include "coupler/scene/scene.hpp"

namespace cosim::scene {

inline constexpr std::array scheme_names{"serial-explicit", "parallel-explicit", "serial-implicit",
                                         "parallel-implicit"};
inline constexpr std::array acceleration_names{"none", "constant", "aitken", "iqn-ils"};
inline constexpr std::array transport_names{"ipc", "tcp"};
inline constexpr std::array effect_names{"gravity",  "buoyancy",     "hydrodynamics", "contact",
                                         "friction", "rarefied_gas", "tracers"};
inline constexpr std::array generator_names{"lattice", "random", "file"};
inline constexpr std::array shape_names{"sphere", "ellipsoid", "box", "cylinder", "capsule", "plane", "mesh"};
inline constexpr std::array data_names{"poses", "forces", "fields"};  // bit i of a DataSet

template <class E, std::size_t N>
E pick(const Reader& r, const std::string& key, const std::array<const char*, N>& names) {
  return static_cast<E>(r.choice(key, names));
}

template <class E, std::size_t N>
E pick(const Reader& r, const std::string& key, const std::array<const char*, N>& names, E fallback) {
  return static_cast<E>(r.choice(key, names, static_cast<std::size_t>(fallback)));
}

}  // namespace cosim::scene
