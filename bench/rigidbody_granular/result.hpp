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
  double wall_seconds = 0;
  // Processor time of the run: on a shared machine the rates use it, not the wall's.
  double cpu_seconds = 0;
  double pairs_tested = 0;   // narrow-phase pair tests over the run
  double heap_bytes = 0;     // live heap held by the engine at the end (malloc's count, mmapped blocks too)
  double peak_rss_bytes = 0; // of the process so far
  double max_penetration = 0;  // deepest sphere/sphere or sphere/wall overlap at the end [m]
  double mean_height = 0;      // of the sphere centres at the end [m]: did it pack?
};

// Sphere/sphere and sphere/wall overlap of the final positions (walls: the box's floor
// and four sides), found with the project's hash grid.
double max_penetration(const std::vector<Eigen::Vector3d>& centres, double radius, double half_width);

// Live heap bytes right now, from glibc's allocator statistics.
double heap_in_use();
double cpu_time();  // of the process, in seconds
double peak_rss();

}  // namespace cosim::bench
