#pragma once
// Physical constants shared by the tracker's libraries (header only).

namespace cosim::tracker {

inline constexpr double boltzmann = 1.380649e-23;  // J/K, exact (SI 2019)

}  // namespace cosim::tracker
