// Random numbers that are the same with every compiler and standard library. Every program
// of a run loads the scene and must make the same bodies from the same seed: the engine
// std::mt19937_64 is fixed bit for bit by the standard, but the distributions of <random>
// are not (libstdc++ and libc++ turn the same bits into different numbers), so the mapping
// to an interval is done here.
#pragma once

#include <cstdint>
#include <random>

namespace cosim::scene {

class Uniform {
 public:
  explicit Uniform(std::uint64_t seed) : engine_(seed) {}

  // A number in [lo, hi] (hi only through rounding): the top 53 bits of one draw as a
  // fraction in [0, 1), scaled.
  double operator()(double lo, double hi) {
    const double fraction = static_cast<double>(engine_() >> 11) * 0x1.0p-53;
    return lo + (hi - lo) * fraction;
  }

 private:
  std::mt19937_64 engine_;
};

}  // namespace cosim::scene
