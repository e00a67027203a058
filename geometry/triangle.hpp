#pragma once

#include <array>
#include <cstdint>

namespace cosim::geometry {

// Corner indices into a vertex array, counter-clockwise seen from outside.
using Triangle = std::array<std::uint32_t, 3>;

}  // namespace cosim::geometry
