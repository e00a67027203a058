#include "rigidbody/dynamics/integrator.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/LU>
#include <stdexcept>

#include "rigidbody/dynamics/leapfrog.hpp"
#include "rigidbody/dynamics/semi_implicit_euler.hpp"

namespace cosim::rigidbody::dynamics {
namespace {

void check(std::span<BodyState> states, std::span<const BodyInertia> inertia, std::span<const WindowWrench> external,
           std::span<const InLiquid> liquid, double t0, double t1, double dt) {
  if (inertia.size() != states.size()) throw std::invalid_argument("advance: one inertia per body state is needed");
  if (!external.empty() && external.size() != states.size())
    throw std::invalid_argument("advance: external wrenches must be one per body or none");
  if (!liquid.empty() && liquid.size() != states.size())
    throw std::invalid_argument("advance: the liquid's share must be one per body or none");
  if (!(t1 >= t0)) throw std::invalid_argument("advance: t1 must not be before t0");
  if (!(dt > 0.0)) throw std::invalid_argument("advance: dt must be positive");
}

// dt is the longest substep: a span that is not a whole number of them takes one more,
// shorter, so nothing stepped at dt (the soft step's springs, capped by the substep) is
// stepped longer. The tolerance keeps a whole number from gaining one by round-off.
long substep_count(double span, double dt) { return std::max(1L, static_cast<long>(std::ceil(span / dt - 1e-9))); }

// The liquid's damping over h, implicitly: m (v' - v) = -h c v', and likewise for omega in
// the body frame with I and the rotational damping. Implicit, so a damping far above m / h
// (a body in a narrow gap) slows the body without overshooting.
void damp(BodyState& state, const BodyInertia& body, const InLiquid& liquid, double h) {
  if (liquid.damping > 0.0) state.velocity /= 1.0 + h * liquid.damping * body.inverse_mass;
  if (!body.rotates || liquid.rotational_damping.isZero(0.0)) return;
  const Eigen::Matrix3d r = state.orientation.toRotationMatrix();
  const Eigen::Vector3d w = r.transpose() * state.angular_velocity;
  const Eigen::Matrix3d inertia = body.inertia_body();
  const Eigen::Matrix3d lhs = inertia + h * liquid.rotational_damping;
  state.angular_velocity = r * Eigen::Vector3d(lhs.partialPivLu().solve(inertia * w));
}

}  // namespace

Substeps::Substeps(std::span<BodyState> states, std::span<const BodyInertia> inertia,
                   std::span<const WindowWrench> external, double t0, double t1, const IntegratorSettings& settings,
                   std::span<const InLiquid> liquid)
    : states_(states),
      inertia_(inertia),
      external_(external),
      liquid_(liquid),
      t0_(t0),
      t1_(t1),
      scheme_(settings.scheme) {
  check(states, inertia, external, liquid, t0, t1, settings.dt);
  const long n = substep_count(t1 - t0, settings.dt);
  count_ = t1 == t0 ? 0 : n;
  length_ = (t1 - t0) / static_cast<double>(n);
  acceleration_.resize(states.size());
  if (scheme_ == Scheme::leapfrog) start_.resize(states.size());
  for (std::size_t i = 0; i < states.size(); ++i) {
    if (!inertia[i].is_fixed())
      acceleration_[i] =
          settings.body_forces.acceleration(inertia[i], liquid.empty() ? 1.0 : liquid[i].own_mass_fraction);
    if (inertia[i].is_fixed() || !inertia[i].rotates) held_.push_back(i);
  }
  held_start_.resize(held_.size());
}

void Substeps::integrate_velocities(long k) {
  const double h = length_;
  const bool leapfrog = scheme_ == Scheme::leapfrog;
  const double t = t0_ + static_cast<double>(k) * h;
  // Semi-implicit Euler takes the wrench at the start of the substep, leapfrog at its midpoint.
  const double s = leapfrog ? t + 0.5 * h : t;
  // integrate_positions() restores what the solvers may have changed of the held bodies.
  if (leapfrog) std::copy(states_.begin(), states_.end(), start_.begin());
  for (std::size_t k = 0; k < held_.size(); ++k) held_start_[k] = states_[held_[k]];
  for (std::size_t i = 0; i < states_.size(); ++i) {
    if (inertia_[i].is_fixed()) continue;
    const Wrench w = external_.empty() ? Wrench{} : external_[i].at(t0_, t1_, s);
    if (leapfrog)
      leapfrog_velocity(states_[i], inertia_[i], w, acceleration_[i], h);
    else
      semi_implicit_velocity(states_[i], inertia_[i], w, acceleration_[i], h);
    if (!liquid_.empty()) damp(states_[i], inertia_[i], liquid_[i], h);
  }
}

void Substeps::integrate_positions() {
  for (std::size_t i = 0; i < states_.size(); ++i) {
    if (inertia_[i].is_fixed()) continue;
    if (scheme_ == Scheme::leapfrog)
      leapfrog_position(states_[i], start_[i], inertia_[i], length_);
    else
      semi_implicit_position(states_[i], inertia_[i], length_);
  }
  // What the solvers may have changed of the held bodies goes back: all of a fixed body's
  // state, a translation-only body's rotation (which neither scheme turns, so after the move).
  for (std::size_t k = 0; k < held_.size(); ++k) {
    BodyState& s = states_[held_[k]];
    if (inertia_[held_[k]].is_fixed()) {
      s = held_start_[k];
    } else {
      s.orientation = held_start_[k].orientation;
      s.angular_velocity = held_start_[k].angular_velocity;
    }
  }
}

void advance(std::span<BodyState> states, std::span<const BodyInertia> inertia, std::span<const WindowWrench> external,
             double t0, double t1, const IntegratorSettings& settings, std::span<const InLiquid> liquid) {
  Substeps substeps(states, inertia, external, t0, t1, settings, liquid);
  for (long k = 0; k < substeps.count(); ++k) {
    substeps.integrate_velocities(k);
    substeps.integrate_positions();
  }
}

}  // namespace cosim::rigidbody::dynamics
