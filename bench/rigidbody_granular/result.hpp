// What one engine's run of the poured-spheres scene measured.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace cosim::bench {

struct RunResult {
  std::string engine;
  std::size_t bodies = 0;
  int steps = 0;
  double dt = 0;  // [s]
  // Of the steps only, set-up excluded (for LIGGGHTS: the loop time its log prints).
  double wall_seconds = 0;
  // Processor time of the run: on a shared machine the rates use it, not the wall's.
  double cpu_seconds = 0;
  double pairs_tested = 0;  // narrow-phase pair tests over the run
  // Live heap held by the engine at the end (malloc's count, mmapped blocks too); for
  // LIGGGHTS, which runs in a child process: its peak resident set above an empty deck's.
  double heap_bytes = 0;
  double peak_rss_bytes = 0;   // of the process so far (LIGGGHTS: of its child process)
  double max_penetration = 0;  // deepest sphere/sphere or sphere/wall overlap at the end [m]
  double mean_height = 0;      // of the sphere centres at the end [m]: did it pack?
  // Height of a uniform bed with the same centre of mass (twice the mean centre height),
  // and the solid fraction of the box below it.
  double pile_height = 0;
  double packing_fraction = 0;
  // Kinetic energy (translation and rotation) every kinetic_every steps from step 0 [J].
  std::vector<double> kinetic_energy{};
  int kinetic_every = 1;
};

// Kinetic-energy samples per run: the engines sample at the same simulated times.
int kinetic_interval(int steps);

// Fills max_penetration, mean_height, pile_height and packing_fraction from the
// final centres.
void measure_pile(RunResult& r, const std::vector<Eigen::Vector3d>& centres, double radius, double half_width);

// Sphere/sphere and sphere/wall overlap of the final positions (walls: the box's floor
// and four sides), found with the project's hash grid.
double max_penetration(const std::vector<Eigen::Vector3d>& centres, double radius, double half_width);

// Live heap bytes right now, from glibc's allocator statistics.
double heap_in_use();
double cpu_time();  // of the process, in seconds
double peak_rss();

}  // namespace cosim::bench
