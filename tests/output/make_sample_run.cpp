// Writes a small, plausible run file for the plot_script test:
//   make_sample_run out.h5 [--no-bodies]
// Two bodies (a ball on a spring and a spinning box), two participants, 200 windows, and
// every 50 windows the fluid's velocity on a 6 x 4 x 5 grid (a solid-body rotation about z)
// with the ball's surface as a point set.
#include <array>
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "coupler/field/field_frame.hpp"
#include "coupler/output/run_file.hpp"

namespace {

using cosim::output::WindowRecord;

constexpr double kWindow = 0.01;

// Body 0 oscillates vertically on a spring; body 1 spins about z and drifts in x.
void add_body_rows(WindowRecord& w, std::size_t body, double t) {
  const double omega = 2.0 * M_PI;
  if (body == 0) {
    const double z = 0.1 * std::cos(omega * t);
    const double vz = -0.1 * omega * std::sin(omega * t);
    w.poses.insert(w.poses.end(), {0, 0, z, 1, 0, 0, 0, 0, 0, vz, 0, 0, 0});
    w.forces.insert(w.forces.end(), {0, 0, -omega * omega * z, 0, 0, 0});
  } else {
    const double half = 0.5 * t;
    w.poses.insert(w.poses.end(), {0.2 * t, 0, 0, std::cos(half), 0, 0, std::sin(half), 0.2, 0, 0, 0, 0, 1.0});
    w.forces.insert(w.forces.end(), {0, 0, 0, 0, 0, 0.05 * std::sin(t)});
  }
}

// u = (-y, x, 0) at the cell centres of [-1, 1] x [-1, 1] x [-0.5, 0.5], and eight points on the
// ball's surface (radius 0.1 about its centre at height z).
cosim::field::FieldFrame rotation(double z) {
  cosim::field::RectilinearGrid grid;
  const std::array<std::size_t, 3> cells{6, 4, 5};
  const std::array<double, 3> lo{-1, -1, -0.5}, hi{1, 1, 0.5};
  for (int d = 0; d < 3; ++d)
    for (std::size_t i = 0; i <= cells[d]; ++i)
      grid.nodes[d].push_back(lo[d] + (hi[d] - lo[d]) * static_cast<double>(i) / static_cast<double>(cells[d]));
  cosim::field::CellField velocity{"velocity", 3, {}};
  for (std::size_t k = 0; k < cells[2]; ++k)
    for (std::size_t j = 0; j < cells[1]; ++j)
      for (std::size_t i = 0; i < cells[0]; ++i) {
        const double x = 0.5 * (grid.nodes[0][i] + grid.nodes[0][i + 1]);
        const double y = 0.5 * (grid.nodes[1][j] + grid.nodes[1][j + 1]);
        velocity.values.insert(velocity.values.end(), {-y, x, 0});
      }
  std::vector<double> surface;
  for (int n = 0; n < 8; ++n) {
    const double angle = M_PI * n / 4;
    surface.insert(surface.end(), {0.1 * std::cos(angle), 0.1 * std::sin(angle), z});
  }
  return {grid, {velocity}, {{"ball", surface}}};
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: make_sample_run out.h5 [--no-bodies]\n");
    return 2;
  }
  const bool bodies = !(argc > 2 && std::string(argv[2]) == "--no-bodies");
  try {
    const std::vector<std::string> names =
        bodies ? std::vector<std::string>{"ball", "box"} : std::vector<std::string>{};
    auto run = cosim::output::RunFile::create(
        argv[1], {"coupling:\n  window: 0.01\n", "sample.yaml", "0000000", "0.1.0", 1}, names, {"rigid", "fluid"});
    for (std::uint64_t k = 0; k < 200; ++k) {
      WindowRecord w;
      w.window = k;
      w.time = static_cast<double>(k + 1) * kWindow;
      w.iterations = 2 + static_cast<int>(k % 5);
      w.residual = 1e-6 * std::exp(-0.01 * static_cast<double>(k)) * (1 + (k % 5));
      w.wall_seconds = 0.02 + 0.005 * std::sin(0.1 * static_cast<double>(k));
      for (std::size_t b = 0; b < names.size(); ++b) add_body_rows(w, b, w.time);
      w.participant_wall_seconds = {{"rigid", 0.002}, {"fluid", 0.015}};
      w.participant_substeps = {{"rigid", 10}, {"fluid", 4}};
      run.append(w);
      if (bodies && k % 50 == 49) run.write_fields("fluid", k, w.time, rotation(0.1 * std::cos(2 * M_PI * w.time)));
    }
    run.set_status("finished", 4.2);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "make_sample_run: %s\n", e.what());
    return 1;
  }
  return 0;
}
