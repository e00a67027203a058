// The benchmark grid and the three benchmark families run over it.
#pragma once

#include <cstddef>
#include <cstring>
#include <vector>

#include <benchmark/benchmark.h>

#include "coupler/protocol/message.hpp"
#include "bench/coupler_roundtrip/transport.hpp"

namespace cosim::bench {

struct Case {
  int participants;
  std::size_t doubles;  // N: per input value (sent twice: window start and end) and output
  Transport transport;
};

// One coupling window as the coupler runs it: an Advance carrying the input at the window
// start and at its end to every participant, a decoded Result (outputs and Stats) back from
// each.
void window(benchmark::State& state, Case c);
// The same scatter/gather with plain ZeroMQ: the same payload frames (two of N doubles out,
// one back), no header, no validation, received in place.
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
    return protocol::Array::of(protocol::Tag::Forces, static_cast<std::uint32_t>(doubles / 6), 6, std::move(v));
  return protocol::Array::of(protocol::Tag::State, 1, static_cast<std::uint32_t>(doubles), std::move(v));
}

// What a participant computes in both benchmarks, so that neither just echoes its input:
// its outputs, from the input at the window start and end (N doubles each, possibly
// unaligned inside a ZeroMQ frame), into a buffer of its own.
inline void answer(const void* start, const void* end, std::vector<double>& outputs) {
  const auto* a = static_cast<const char*>(start);
  const auto* b = static_cast<const char*>(end);
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    double x, y;
    std::memcpy(&x, a + i * sizeof(double), sizeof(double));
    std::memcpy(&y, b + i * sizeof(double), sizeof(double));
    outputs[i] = 0.5 * (x + y);
  }
}

// Payload bytes crossing the sockets per window, both directions: 2N out and N back per
// participant.
inline double window_bytes(const Case& c) {
  return 3.0 * c.participants * static_cast<double>(c.doubles) * sizeof(double);
}

}  // namespace cosim::bench
