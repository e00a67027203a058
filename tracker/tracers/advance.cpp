#include "tracker/tracers/advance.hpp"

#include <cmath>

namespace cosim::tracker::tracers {
namespace {

// The displacement over h and the velocity at its end.
struct Step {
  Vec3 displacement;
  Vec3 velocity;
};

Step massless(const VelocityField& u, const Vec3& x, double h) {
  const Vec3 k1 = u(x);
  const Vec3 k2 = u(x + 0.5 * h * k1);
  const Vec3 k3 = u(x + 0.5 * h * k2);
  const Vec3 k4 = u(x + h * k3);
  const Vec3 d = h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  return {d, u(x + d)};
}

Step inertial(const VelocityField& u, const Vec3& x, const Vec3& v, double h, double tau) {
  const double decay = std::exp(-h / tau);
  // The fluid velocity where the tracer is half way, from a first estimate of the path.
  const Vec3 u0 = u(x);
  const Vec3 estimate = 0.5 * (h * u0 + tau * (v - u0) * (1.0 - decay));
  const Vec3 um = u(x + estimate);
  return {h * um + tau * (v - um) * (1.0 - decay), um + (v - um) * decay};
}

}  // namespace

bool advance_tracer(const tracking::MoveContext& step, const VelocityField& u, const TracerModel& model,
                    tracking::Particle& tracer, std::span<csg::State> states, double dt) {
  const int substeps = std::max(1, model.substeps);
  const double h = dt / substeps;
  for (int s = 0; s < substeps; ++s) {
    const Step planned =
        model.response_time > 0.0 ? inertial(u, tracer.x, tracer.v, h, model.response_time) : massless(u, tracer.x, h);
    const Vec3 segment = planned.displacement / h;
    tracer.v = segment;
    const tracking::MoveResult result = tracking::move(step, tracer, states, h);
    if (result.removed) return false;
    // Not reflected: the segment ran as planned and the tracer has the step's velocity.
    if (tracer.v == segment) tracer.v = planned.velocity;
  }
  return true;
}

}  // namespace cosim::tracker::tracers
