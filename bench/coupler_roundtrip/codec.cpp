#include "bench/coupler_roundtrip/cases.hpp"
#include "coupler/protocol/messages.hpp"

namespace cosim::bench {
namespace {

protocol::Message result(std::size_t doubles) {
  protocol::Message m = protocol::messages::result(0, 1, {payload(doubles)});
  m.header.participant = "solver0";  // as the participant's Client sends it
  return m;
}

void count_bytes(benchmark::State& state, std::size_t doubles) {
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * doubles * sizeof(double)));
}

}  // namespace

void encode_only(benchmark::State& state, std::size_t doubles) {
  const protocol::Message m = result(doubles);
  for (auto _ : state) benchmark::DoNotOptimize(protocol::encode(m));
  count_bytes(state, doubles);
}

void decode_only(benchmark::State& state, std::size_t doubles) {
  const auto frames = protocol::encode(result(doubles));
  for (auto _ : state) benchmark::DoNotOptimize(protocol::decode(frames));
  count_bytes(state, doubles);
}

}  // namespace cosim::bench
