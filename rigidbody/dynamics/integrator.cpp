#include "rigidbody/dynamics/integrator.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "rigidbody/dynamics/leapfrog.hpp"
#include "rigidbody/dynamics/semi_implicit_euler.hpp"

namespace cosim::dynamics {
namespace {

void check(std::span<BodyState> states, std::span<const BodyInertia> inertia,
           std::span<const WindowWrench> external, double t0, double t1, double dt) {
  if (inertia.size() != states.size())
    throw std::invalid_argument("advance: one inertia per body state is needed");
  if (!external.empty() && external.size() != states.size())
    throw std::invalid_argument("advance: external wrenches must be one per body or none");
  if (!(t1 >= t0)) throw std::invalid_argument("advance: t1 must not be before t0");
  if (!(dt > 0.0)) throw std::invalid_argument("advance: dt must be positive");
}

}  // namespace

long substep_count(double span, double dt) { return std::max(1L, std::lround(span / dt)); }

void advance(std::span<BodyState> states, std::span<const BodyInertia> inertia,
             std::span<const WindowWrench> external, double t0, double t1,
             const IntegratorSettings& settings, const VelocityHook& hook,
             const PositionHook& after_positions) {
  check(states, inertia, external, t0, t1, settings.dt);
  if (t1 == t0) return;
  const long n = substep_count(t1 - t0, settings.dt);
  const double h = (t1 - t0) / static_cast<double>(n);
  const bool leapfrog = settings.scheme == Scheme::leapfrog;

  std::vector<Eigen::Vector3d> acceleration(states.size());
  for (std::size_t i = 0; i < states.size(); ++i)
    if (!inertia[i].is_fixed()) acceleration[i] = settings.body_forces.acceleration(inertia[i]);
  std::vector<BodyState> start;

  for (long k = 0; k < n; ++k) {
    const double t = t0 + static_cast<double>(k) * h;
    // Semi-implicit Euler takes the wrench at the start of the substep, leapfrog at its midpoint.
    const double s = leapfrog ? t + 0.5 * h : t;
    start.assign(states.begin(), states.end());
    for (std::size_t i = 0; i < states.size(); ++i) {
      if (inertia[i].is_fixed()) continue;
      const Wrench w = external.empty() ? Wrench{} : external[i].at(t0, t1, s);
      if (leapfrog)
        leapfrog_velocity(states[i], inertia[i], w, acceleration[i], h);
      else
        semi_implicit_velocity(states[i], inertia[i], w, acceleration[i], h);
    }
    if (hook) hook(h, states);
    for (std::size_t i = 0; i < states.size(); ++i) {
      if (inertia[i].is_fixed()) {
        states[i] = start[i];
        continue;
      }
      if (!inertia[i].rotates) {
        states[i].orientation = start[i].orientation;
        states[i].angular_velocity = start[i].angular_velocity;
      }
      if (leapfrog)
        leapfrog_position(states[i], start[i], inertia[i], h);
      else
        semi_implicit_position(states[i], inertia[i], h);
    }
    if (after_positions) after_positions(h, states);
  }
}

}  // namespace cosim::dynamics
