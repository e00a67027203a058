// The benchmark grid and the three benchmark families run over it.
#pragma once

#include <cstddef>

#include <benchmark/benchmark.h>

#include "protocol/message.hpp"
#include "transport.hpp"

namespace cosim::bench {

struct Case {
  int participants;
  std::size_t doubles;  // per message, each way
  Transport transport;
};

// One coupling window: Advance to every participant, a decoded Result back from each.
void window(benchmark::State& state, Case c);
// The same scatter/gather with plain ZeroMQ: one frame of the same bytes each way, no
// header, no validation, received in place.
void raw(benchmark::State& state, Case c);
// encode() or decode() alone, no sockets.
void encode_only(benchmark::State& state, std::size_t doubles);
void decode_only(benchmark::State& state, std::size_t doubles);

// N doubles as a participant would exchange them: Forces of N/6 bodies when N allows,
// else an opaque State row (not checked for NaN/Inf, so a little cheaper to decode).
inline protocol::Array payload(std::size_t doubles) {
  std::vector<double> v(doubles);
  for (std::size_t i = 0; i < doubles; ++i) v[i] = 1.0 + 1e-3 * static_cast<double>(i % 1000);
  if (doubles % 6 == 0)
    return protocol::Array::of(protocol::Tag::Forces, static_cast<std::uint32_t>(doubles / 6), 6,
                               std::move(v));
  return protocol::Array::of(protocol::Tag::State, 1, static_cast<std::uint32_t>(doubles),
                             std::move(v));
}

// Bytes crossing the sockets per window, both directions.
inline double window_bytes(const Case& c) {
  return 2.0 * c.participants * static_cast<double>(c.doubles) * sizeof(double);
}

}  // namespace cosim::bench
