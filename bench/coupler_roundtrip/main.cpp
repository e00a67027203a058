// Coupling-window round trips per second for 2 and 3 participants with N = 1, 1000 and 1e6
// doubles per input and output (2N out, N back) over ipc, tcp, and tcp with CURVE on
// 127.0.0.2 (as across hosts), next to a raw ZeroMQ exchange of the same bytes, then a table
// of the overhead. Extra arguments go to Google Benchmark (--benchmark_filter=...).
#include <benchmark/benchmark.h>

#include "bench/coupler_roundtrip/cases.hpp"
#include "bench/coupler_roundtrip/summary.hpp"

using namespace cosim::bench;

namespace {

// Three short repetitions and their median resist a busy machine better than one long
// run; the grid stays under a minute.
void timing(benchmark::internal::Benchmark* b) {
  b->MinTime(0.2)->Repetitions(3)->DisplayAggregatesOnly()->Unit(benchmark::kMicrosecond);
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<Case> cases;
  for (int participants : {2, 3})
    for (std::size_t doubles : {std::size_t{1}, std::size_t{1000}, std::size_t{1000000}})
      for (Transport t : {Transport::Ipc, Transport::Tcp, Transport::Curve})
        cases.push_back({participants, doubles, t});

  // Participants are threads: wall time is what a window costs.
  for (const Case& c : cases) {
    timing(benchmark::RegisterBenchmark(Summary::window_name(c).c_str(), window, c)->UseRealTime());
    timing(benchmark::RegisterBenchmark(Summary::raw_name(c).c_str(), raw, c)->UseRealTime());
  }
  constexpr std::size_t kBig = 1000000;
  timing(benchmark::RegisterBenchmark("codec/encode/n1000000", encode_only, kBig));
  timing(benchmark::RegisterBenchmark("codec/decode/n1000000", decode_only, kBig));

  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  Summary summary;
  benchmark::RunSpecifiedBenchmarks(&summary);
  summary.print_table(cases);
  benchmark::Shutdown();
}
