// The scene in LIGGGHTS, run as a child process on one core: the bench writes the deck,
// runs it, and reads back the loop time, the kinetic energy and the final positions.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>

#include "bench/rigidbody_granular/child_process.hpp"
#include "bench/rigidbody_granular/engines.hpp"
#include "bench/rigidbody_granular/liggghts.hpp"

namespace cosim::bench {

namespace {

struct Deck {
  ChildUsage usage;
  std::filesystem::path output;
};

// One deck in `directory`: liggghts -in name -log none -echo none, screen to name.out.
// Serial by construction (no mpirun: one MPI rank, one core).
Deck run_deck(const std::filesystem::path& liggghts, const std::filesystem::path& directory, const std::string& name,
              const std::string& deck) {
  std::ofstream(directory / name) << deck;
  const std::filesystem::path output = directory / (name + ".out");
  const ChildUsage usage = run_child(liggghts, {"-in", name, "-log", "none", "-echo", "none"}, directory, output);
  if (usage.exit_code != 0)
    throw std::runtime_error("liggghts " + name + " exited with " + std::to_string(usage.exit_code) + ", see " +
                             output.string());
  return {usage, output};
}

LiggghtsLog read_log(const Deck& deck) {
  std::ifstream in(deck.output);
  std::optional<LiggghtsLog> log = read_liggghts_log(in);
  if (!log) throw std::runtime_error("no loop time in " + deck.output.string());
  return *log;
}

std::filesystem::path temporary_directory() {
  std::string pattern = (std::filesystem::temp_directory_path() / "rigidbody_granular_liggghts.XXXXXX").string();
  if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("cannot make a directory from " + pattern);
  return pattern;
}

}  // namespace

std::optional<RunResult> run_liggghts(const PourScene& scene, const LiggghtsRun& run) {
  const std::optional<std::filesystem::path> liggghts = find_executable(run.executable);
  if (!liggghts) {
    std::printf("# liggghts: skipped, no executable '%s' on PATH (Debian: apt-get install liggghts)\n",
                run.executable.c_str());
    return std::nullopt;
  }
  const bool keep = !run.directory.empty();
  const std::filesystem::path directory =
      keep ? std::filesystem::path(run.directory) / ("n" + std::to_string(scene.positions.size()))
           : temporary_directory();
  std::filesystem::create_directories(directory);
  write_liggghts_data(scene, directory / "spheres.data");

  RunResult r{.engine = "liggghts", .bodies = scene.positions.size(), .steps = dem_steps(scene), .dt = scene.dem_dt};
  r.kinetic_every = kinetic_interval(r.steps);
  // Three decks: an empty one (the executable's own resident set, libraries and MPI), the
  // scene with no steps (reading, neighbour lists, first forces, the final dump), and the
  // scene. The set-up's processor time is taken off the scene's, as the other engines
  // start their clocks after building the scene.
  const Deck empty = run_deck(*liggghts, directory, "empty.in", "units si\n");
  const Deck setup = run_deck(*liggghts, directory, "setup.in",
                              liggghts_deck(scene, 0, r.kinetic_every, "spheres.data", "setup.dump"));
  const Deck full = run_deck(*liggghts, directory, "pour.in",
                             liggghts_deck(scene, r.steps, r.kinetic_every, "spheres.data", "final.dump"));
  const LiggghtsLog log = read_log(full);
  read_log(setup);  // throws unless the set-up run reached its (empty) loop
  if (log.atoms != r.bodies || log.steps != r.steps)
    throw std::runtime_error("liggghts ran " + std::to_string(log.atoms) + " atoms for " + std::to_string(log.steps) +
                             " steps, see " + full.output.string());
  std::printf("# liggghts: %s, %s\n", log.version.c_str(), liggghts->c_str());

  r.pairs_tested = std::nan("");  // its neighbour list is not a count of pair tests
  r.wall_seconds = log.loop_seconds;
  r.cpu_seconds = full.usage.cpu_seconds - setup.usage.cpu_seconds;
  // A loop shorter than the two processes' start-up scatter has no measurable time.
  if (r.cpu_seconds <= 0) r.cpu_seconds = std::nan("");
  r.peak_rss_bytes = full.usage.peak_rss_bytes;
  r.heap_bytes = full.usage.peak_rss_bytes - empty.usage.peak_rss_bytes;
  r.kinetic_energy = log.kinetic_energy;
  std::ifstream dump(directory / "final.dump");
  const std::vector<Eigen::Vector3d> centres = read_liggghts_dump(dump);
  if (centres.size() != r.bodies)
    throw std::runtime_error("final.dump holds " + std::to_string(centres.size()) + " atoms");
  measure_pile(r, centres, scene.radius, scene.half_width);
  if (!keep) std::filesystem::remove_all(directory);
  return r;
}

}  // namespace cosim::bench
