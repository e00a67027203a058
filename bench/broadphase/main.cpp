// Broad-phase throughput: one step is update() plus find_pairs() on a fixed scene, the
// grid rebuilt from scratch as in a simulation. Counters: object updates per second,
// candidate pairs per second, bytes held per object; the brute force only at N = 1e3.
#include <benchmark/benchmark.h>

#include "rigidbody/broadphase/brute_force.hpp"
#include "rigidbody/broadphase/hash_grid.hpp"
#include "tests/rigidbody/broadphase/scenes.hpp"

namespace cosim::rigidbody::broadphase {
namespace {

constexpr double kSolidFraction = 0.55;
// A contact-persistence margin, a tenth of the (smallest) radius.
constexpr double kMargin = 0.1;

void report(benchmark::State& state, std::size_t objects, std::size_t pairs) {
  using benchmark::Counter;
  constexpr auto rate = Counter::kIsIterationInvariantRate;
  state.counters["updates/s"] = Counter(static_cast<double>(objects), rate);
  state.counters["pairs/s"] = Counter(static_cast<double>(pairs), rate);
  state.counters["pairs/object"] = static_cast<double>(pairs) / static_cast<double>(objects);
}

void grid_steps(benchmark::State& state, const std::vector<Object>& objects, double level_factor = 2.0) {
  HashGrid grid({.margin = kMargin, .level_factor = level_factor});
  std::vector<Pair> pairs;
  for (auto _ : state) {
    grid.update(objects);
    grid.find_pairs(pairs);
    benchmark::DoNotOptimize(pairs.data());
  }
  report(state, objects.size(), pairs.size());
  state.counters["bytes/object"] = static_cast<double>(grid.memory_bytes()) / static_cast<double>(objects.size());
  state.counters["levels"] = static_cast<double>(grid.level_count());
}

void BM_GridPacked(benchmark::State& state) {
  grid_steps(state, scenes::packed(static_cast<std::size_t>(state.range(0)), kSolidFraction, 1));
}

// Radii from 1 to 10; the second argument is the level factor (five levels with 2, three
// with 4).
void BM_GridPolydisperse(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  grid_steps(state, scenes::polydisperse(n, 0.5, 10.0, 1), static_cast<double>(state.range(1)));
}

void BM_BruteForcePacked(benchmark::State& state) {
  const std::vector<Object> objects = scenes::packed(static_cast<std::size_t>(state.range(0)), kSolidFraction, 1);
  std::size_t pairs = 0;
  for (auto _ : state) {
    pairs = brute_force_pairs(objects, kMargin).size();
    benchmark::ClobberMemory();
  }
  report(state, objects.size(), pairs);
}

BENCHMARK(BM_GridPacked)->RangeMultiplier(10)->Range(1000, 100000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_GridPolydisperse)->ArgsProduct({{1000, 10000, 100000}, {2, 4}})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_BruteForcePacked)->Arg(1000)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace cosim::rigidbody::broadphase

BENCHMARK_MAIN();
