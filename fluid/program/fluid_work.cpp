#include "fluid/program/fluid_work.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <variant>

#include "fluid/ibm/immersed_boundary.hpp"
#include "fluid/navier_stokes/time_step_controller.hpp"
#include "fluid/program/body_surfaces.hpp"
#include "fluid/program/settling_speed.hpp"

namespace cosim::fluid::program {
namespace {

constexpr std::uint64_t kCellValues = 5;   // velocity (3), pressure, alpha: cell_fields.hpp
constexpr std::uint64_t kPointValues = 3;  // x, y, z of a surface point: body_surfaces.hpp
// The checkpoint state (FluidSolver::state): velocity (3), pressure and the last step's
// convection (3) per cell, the faces on the domain's boundary aside, and the forcing's
// impulse (3) per marker.
constexpr std::uint64_t kStateCellValues = 7, kStateMarkerValues = 3;

// The largest convective rate, sum_d |u_d| / h_d over the finest cells, the run is expected
// to reach: from the initial velocity and every inflow's and moving wall's velocity (sampled
// over the face), sped up past bodies in that flow by the potential flow's largest factor
// (2 past a cylinder, taken for a two-dimensional grid, 1.5 past a sphere), and from the
// speed each free body settles at under gravity (settling_speed.hpp). A flow that speeds up
// otherwise (a jet, a wake that sheds) takes smaller steps than this: a scene's recorded
// run corrects the next estimate for that (bench/estimate/README.md).
double peak_rate(const FluidSetup& setup, const scene::Scene& scene) {
  std::array<double, 3> h{};
  bool two_dimensional = false;
  for (std::size_t d = 0; d < 3; ++d) {
    h[d] = setup.axes[d].max_width();
    for (int i = 0; i < setup.axes[d].cells(); ++i) h[d] = std::min(h[d], setup.axes[d].width(i));
    two_dimensional = two_dimensional || setup.axes[d].cells() == 1;
  }
  const auto rate = [&](const Eigen::Vector3d& u) {
    double r = 0;
    for (std::size_t d = 0; d < 3; ++d)
      if (setup.axes[d].cells() > 1) r += std::abs(u[static_cast<Eigen::Index>(d)]) / h[d];
    return r;
  };
  const auto point = [](const fluid::grid::Point& u) { return Eigen::Vector3d(u[0], u[1], u[2]); };
  double flow = rate(point(setup.initial_velocity));
  constexpr int kSamples = 9;  // per direction across a face
  for (std::size_t face = 0; face < setup.boundaries.size(); ++face) {
    const fluid::grid::Boundary& b = setup.boundaries[face];
    if (!b.velocity) continue;
    const std::size_t normal = face / 2, u = (normal + 1) % 3, v = (normal + 2) % 3;
    fluid::grid::Point x{};
    x[normal] = face % 2 == 0 ? setup.axes[normal].lo() : setup.axes[normal].hi();
    for (int i = 0; i < kSamples; ++i)
      for (int j = 0; j < kSamples; ++j) {
        x[u] = setup.axes[u].lo() + (i + 0.5) / kSamples * (setup.axes[u].hi() - setup.axes[u].lo());
        x[v] = setup.axes[v].lo() + (j + 0.5) / kSamples * (setup.axes[v].hi() - setup.axes[v].lo());
        flow = std::max(flow, rate(point(b.velocity(x, 0.0))));
      }
  }
  if (!setup.bodies.empty()) flow *= two_dimensional ? 2.0 : 1.5;
  const Eigen::Vector3d g(scene.gravity[0], scene.gravity[1], scene.gravity[2]);
  const bool falling = scene.has_effect(scene::Effect::Gravity) && g.norm() > 0;
  for (std::size_t b = 0; b < setup.bodies.size() && b < scene.bodies.size(); ++b) {
    const scene::Body& body = scene.bodies[b];
    const fluid::bodies::RigidBody& held = setup.bodies[b];
    flow = std::max(flow, rate(held.velocity));
    if (body.fixed || !falling) continue;
    const double diameter = std::cbrt(6 * geometry::volume(held.shape) / std::numbers::pi);
    flow =
        std::max(flow, rate(g.normalized() * settling_speed(diameter, body.material.density, setup.properties.density,
                                                            setup.properties.viscosity, g.norm())));
  }
  return flow;
}

// The mean step over a window the run is expected to take: the window over the steps the
// controller takes in it at the peak rate.
double expected_dt(const FluidSetup& setup, const scene::Scene& scene) {
  const double window = scene.coupling.window;
  const auto windows = static_cast<long>(scene.windows());
  const fluid::navier_stokes::TimeStepController controller(setup.steps);
  const double steps = controller.steps_per_window(peak_rate(setup, scene), window, std::max(1L, windows));
  return steps > 0 ? window / steps : setup.steps.dt_max;
}

}  // namespace

participant::WorkReport fluid_work(const FluidSetup& setup, const scene::Scene& scene) {
  const fluid::grid::Axes axes{setup.axes[0], setup.axes[1], setup.axes[2]};
  std::uint64_t cells = 1;
  for (const fluid::grid::Axis& axis : axes) cells *= static_cast<std::uint64_t>(axis.cells());

  // The solver's own placement (retraction, thinning, the section on a two-dimensional
  // grid): the count depends on each body's cell width and curvature, so no formula would
  // match it. Equal shapes are sampled once (geometry::SampledShapes).
  std::uint64_t markers = 0;
  if (const auto* ibm = std::get_if<fluid::ibm::IbmOptions>(&setup.body_method))
    markers = fluid::ibm::ImmersedBoundary::marker_count(axes, *ibm, setup.bodies);

  geometry::SampledShapes sampled;
  std::uint64_t points = 0;
  for (const fluid::bodies::RigidBody& body : setup.bodies) points += surface_points(axes, body, sampled).size();

  return {.program = "fluid",
          .per_step = {{"cells", cells}, {"markers", markers}},
          .held = {{"cells", cells}, {"markers", markers}},
          .frame_bytes = (kCellValues * cells + kPointValues * points) * sizeof(double),
          .state_bytes = (kStateCellValues * cells + kStateMarkerValues * markers) * sizeof(double),
          .dt = expected_dt(setup, scene)};
}

}  // namespace cosim::fluid::program
