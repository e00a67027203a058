// The run file's write cost per window: 2000 appends (4 bodies, 2 participants), a
// checkpoint of 0.8 MB every 10 windows and a field step of 1 MB (32^3 cells, p and u)
// every 20, through RunFile as the coupler writes them.
//   run_file_writes [file]   (default run_file_writes.h5 in the current folder)
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "coupler/output/run_file.hpp"

namespace {

using Clock = std::chrono::steady_clock;
double micros(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::micro>(b - a).count();
}

}  // namespace

int main(int argc, char** argv) {
  using namespace cosim;
  const std::filesystem::path path = argc > 1 ? argv[1] : "run_file_writes.h5";
  const std::vector<std::string> bodies{"a", "b", "c", "d"}, participants{"fluid", "rigid"};
  constexpr int kWindows = 2000;
  output::RunFile run = output::RunFile::create(path, output::RunInfo{"s", "s", "g", "v", 1}, bodies, participants);
  const std::vector<double> state(100000, 1.0);
  field::RectilinearGrid grid;
  for (auto& axis : grid.nodes)
    for (int i = 0; i <= 32; ++i) axis.push_back(i);
  const field::FieldFrame frame{
      grid, {{"p", 1, std::vector<double>(32768, 1.0)}, {"u", 3, std::vector<double>(3 * 32768, 2.0)}}};
  double append = 0, checkpoint = 0, fields = 0;
  int checkpoints = 0, steps = 0;
  for (int k = 0; k < kWindows; ++k) {
    output::WindowRecord w;
    w.window = k;
    w.time = 0.1 * (k + 1);
    w.poses.assign(13 * bodies.size(), 0.5 * k);
    w.forces.assign(6 * bodies.size(), 0.25 * k);
    for (const std::string& p : participants) w.participant_wall_seconds[p] = w.participant_substeps[p] = 1.0;
    const auto t0 = Clock::now();
    run.append(w);
    const auto t1 = Clock::now();
    append += micros(t0, t1);
    if (k % 10 == 9) {
      run.write_checkpoint(output::Checkpoint{std::uint64_t(k + 1), w.time, w.poses, w.forces, {{"fluid", state}}, {}});
      checkpoint += micros(t1, Clock::now());
      ++checkpoints;
    }
    if (k % 20 == 0) {
      const auto t2 = Clock::now();
      run.write_fields("fluid", k, w.time, frame);
      fields += micros(t2, Clock::now());
      ++steps;
    }
  }
  std::printf("append %.0f us a window, checkpoint of 0.8 MB %.0f us, field step of 1 MB %.0f us\n", append / kWindows,
              checkpoint / checkpoints, fields / steps);
}
