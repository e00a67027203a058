#include "rigidbody/solver/lubrication.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "rigidbody/solver/contact_frame.hpp"

namespace cosim::rigidbody::solver {

void apply_lubrication(const ContactScene& scene, std::span<const double> radii, const LubricationOptions& options) {
  if (!options.active()) return;
  for (const contact::PairContacts& pair : scene.contacts.pairs) {
    const std::span<const contact::ContactPoint> points = scene.contacts.points_of(pair);
    const contact::ContactPoint& p = *std::min_element(
        points.begin(), points.end(), [](const auto& x, const auto& y) { return x.distance < y.distance; });
    if (p.distance >= options.range) continue;
    // A plane's curvature is zero: R is then the other body's radius.
    const double curvature = 1.0 / radii[pair.a] + 1.0 / radii[pair.b];
    const double r = 1.0 / curvature;
    const double gap = std::max(p.distance, options.roughness);
    const double damping = 6.0 * std::numbers::pi * options.viscosity * r * r * (1.0 / gap - 1.0 / options.range);
    const ContactFrame frame = make_frame(pair, p, scene.states);
    const double response = frame.local_response(scene.mobility)(0, 0);
    if (response == 0.0) continue;
    // v_n' = v_n - response J and J = -damping dt v_n' give the backward-Euler impulse.
    const double vn = frame.local_velocity(scene.states).x();
    const double impulse = -damping * scene.dt * vn / (1.0 + damping * scene.dt * response);
    frame.apply_local({impulse, 0.0, 0.0}, scene.states, scene.mobility);
  }
}

}  // namespace cosim::rigidbody::solver
