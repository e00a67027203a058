#include "fluid/program/fluid_work.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <variant>

#include "fluid/ibm/immersed_boundary.hpp"
#include "fluid/program/body_surfaces.hpp"

namespace cosim::program {
namespace {

constexpr std::uint64_t kCellValues = 5;   // velocity (3), pressure, alpha: cell_fields.hpp
constexpr std::uint64_t kPointValues = 3;  // x, y, z of a surface point: body_surfaces.hpp
// The checkpoint state (FluidSolver::state): velocity (3), pressure and the last step's
// convection (3) per cell, the faces on the domain's boundary aside, and the forcing's
// impulse (3) per marker.
constexpr std::uint64_t kStateCellValues = 7, kStateMarkerValues = 3;

// The step the CFL limit allows at the start, from the initial velocity and every inflow's
// and moving wall's velocity (sampled over the face) over the finest cells; the scene's dt
// where that is smaller. A flow that speeds up past the bodies, or bodies that move fast,
// take smaller steps than this: a scene's recorded run corrects the next estimate for that.
double starting_dt(const FluidSetup& setup) {
  std::array<double, 3> h{};
  for (std::size_t d = 0; d < 3; ++d) {
    h[d] = setup.axes[d].max_width();
    for (int i = 0; i < setup.axes[d].cells(); ++i) h[d] = std::min(h[d], setup.axes[d].width(i));
  }
  const auto rate = [&](const fluid::Point& u) {
    double r = 0;
    for (std::size_t d = 0; d < 3; ++d) r += std::abs(u[d]) / h[d];
    return r;
  };
  double fastest = rate(setup.initial_velocity);
  constexpr int kSamples = 9;  // per direction across a face
  for (std::size_t face = 0; face < setup.boundaries.size(); ++face) {
    const fluid::Boundary& b = setup.boundaries[face];
    if (!b.velocity) continue;
    const std::size_t normal = face / 2, u = (normal + 1) % 3, v = (normal + 2) % 3;
    fluid::Point x{};
    x[normal] = face % 2 == 0 ? setup.axes[normal].lo() : setup.axes[normal].hi();
    for (int i = 0; i < kSamples; ++i)
      for (int j = 0; j < kSamples; ++j) {
        x[u] = setup.axes[u].lo() + (i + 0.5) / kSamples * (setup.axes[u].hi() - setup.axes[u].lo());
        x[v] = setup.axes[v].lo() + (j + 0.5) / kSamples * (setup.axes[v].hi() - setup.axes[v].lo());
        fastest = std::max(fastest, rate(b.velocity(x, 0.0)));
      }
  }
  return fastest > 0 ? std::min(setup.steps.dt_max, setup.steps.cfl / fastest) : setup.steps.dt_max;
}

}  // namespace

participant::WorkReport fluid_work(const FluidSetup& setup) {
  const fluid::Axes axes{setup.axes[0], setup.axes[1], setup.axes[2]};
  std::uint64_t cells = 1;
  for (const fluid::Axis& axis : axes) cells *= static_cast<std::uint64_t>(axis.cells());

  // The solver's own placement (retraction, thinning, the section on a two-dimensional
  // grid): the count depends on each body's cell width and curvature, so no formula would
  // match it. Equal shapes are sampled once (geometry::SampledShapes).
  std::uint64_t markers = 0;
  if (const auto* ibm = std::get_if<fluid::IbmOptions>(&setup.body_method))
    markers = fluid::ImmersedBoundary::marker_count(axes, *ibm, setup.bodies);

  geometry::SampledShapes sampled;
  std::uint64_t points = 0;
  for (const fluid::RigidBody& body : setup.bodies) points += surface_points(axes, body, sampled).size();

  return {.program = "fluid",
          .per_step = {{"cells", cells}, {"markers", markers}},
          .held = {{"cells", cells}, {"markers", markers}},
          .frame_bytes = (kCellValues * cells + kPointValues * points) * sizeof(double),
          .state_bytes = (kStateCellValues * cells + kStateMarkerValues * markers) * sizeof(double),
          .dt = starting_dt(setup)};
}

}  // namespace cosim::program
