// rigidbody_accuracy: what accuracy costs in time for the rigid-body contact solvers, on a
// settling pyramid of 91 spheres and a resting stack of 10 boxes, or (--hard) on the
// stability suite's hard resting cases. Prints one row per run,
// optionally writes them as CSV, and exits 1 if a run breaks a sanity bound (sanity.cpp).
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>

#include "bench/rigidbody_accuracy/sanity.hpp"
#include "bench/rigidbody_accuracy/sweep.hpp"
#include "bench/rigidbody_accuracy/table.hpp"

using namespace cosim::bench;

int main(int argc, char** argv) {
  CLI::App app{"rigidbody_accuracy: accuracy against wall time of the rigid-body contact solvers"};
  bool quick = false;
  bool hard = false;
  std::string csv;
  app.add_flag("--quick", quick,
               "One run per solver and scene: SI at its defaults, PGS and Jacobi at 20 iterations (seconds)");
  app.add_flag(
      "--hard", hard,
      "The stability suite's hard cases (mass and size ratios, pyramids at friction 5, a 20-box tower), 10 s each, soft / SI / PGS / DEM side by side");
  app.add_option("--csv", csv, "Also write the table to this CSV file");
  CLI11_PARSE(app, argc, argv);

  try {
    std::vector<Run> runs;
    print_header();
    const std::vector<SceneBuilder> scenes =
        hard ? hard_scenes() : std::vector<SceneBuilder>{build_pyramid, build_box_stack};
    for (const SceneBuilder& scene : scenes) {
      // A scene at rest is compared with its start; the settling pyramid has no exact end
      // state, so the full sweep compares it with a reference run (quick: no error).
      std::vector<Eigen::Vector3d> end_state;
      cosim::rigidbody::world::World probe;
      if (!quick && !hard && !scene(probe).at_rest) {
        runs.push_back(run(reference(scene)));
        print_row(runs.back());
        end_state = runs.back().end_positions;
      }
      for (const RunSpec& spec : hard ? hard_sweep(scene) : quick ? quick_sweep(scene) : full_sweep(scene)) {
        runs.push_back(run(spec, end_state));
        print_row(runs.back());
      }
    }
    if (!csv.empty()) write_csv(csv, runs);
    const std::vector<std::string> failures = sanity_failures(runs);
    for (const std::string& f : failures) std::fprintf(stderr, "rigidbody_accuracy: FAILED: %s\n", f.c_str());
    return failures.empty() ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rigidbody_accuracy: %s\n", e.what());
    return 1;
  }
}
