// rigidbody_accuracy: what accuracy costs in time for the rigid-body contact solvers, on a
// settling pyramid of 91 spheres and a resting stack of 10 boxes. Prints one row per run,
// optionally writes them as CSV, and exits 1 if a run breaks a sanity bound (sanity.cpp).
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>

#include "sanity.hpp"
#include "sweep.hpp"
#include "table.hpp"

using namespace cosim::bench;

int main(int argc, char** argv) {
  CLI::App app{"rigidbody_accuracy: accuracy against wall time of the rigid-body contact solvers"};
  bool quick = false;
  std::string csv;
  app.add_flag("--quick", quick, "One run per solver and scene: SI at its defaults, PGS and Jacobi at 20 iterations (seconds)");
  app.add_option("--csv", csv, "Also write the table to this CSV file");
  CLI11_PARSE(app, argc, argv);

  try {
    std::vector<Run> runs;
    print_header();
    for (SceneBuilder scene : {build_pyramid, build_box_stack}) {
      // A scene at rest is compared with its start; the settling pyramid has no exact end
      // state, so the full sweep compares it with a reference run (quick: no error).
      std::vector<Eigen::Vector3d> end_state;
      cosim::world::World probe;
      if (!quick && !scene(probe).at_rest) {
        runs.push_back(run(reference(scene)));
        print_row(runs.back());
        end_state = runs.back().end_positions;
      }
      for (const RunSpec& spec : quick ? quick_sweep(scene) : full_sweep(scene)) {
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
