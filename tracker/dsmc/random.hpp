#pragma once
// The DSMC random numbers: PCG (O'Neill 2014, Debian libpcg-cpp-dev), pcg64, which is
// fast (one 128-bit multiply-add per draw), small (32 bytes of state) and has 2^127
// independent streams selected by the second seed, so every rank (or thread) gets its own
// stream of one seed and a run is reproducible for a given seed and rank count.

#include <pcg_random.hpp>

#include <cstdint>

namespace cosim::tracker::dsmc {

using Rng = pcg64;

// Generator `stream` (rank, thread) of `seed`.
inline Rng make_rng(std::uint64_t seed, std::uint64_t stream = 0) { return Rng(seed, stream); }

// Uniform in [0, 1): the top 53 bits of one draw.
inline double uniform(Rng& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

// Uniform in (0, 1]: for logarithms and powers with negative exponents.
inline double uniform_open0(Rng& rng) { return (static_cast<double>(rng() >> 11) + 1.0) * 0x1.0p-53; }

}  // namespace cosim::tracker::dsmc
