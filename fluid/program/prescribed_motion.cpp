#include "fluid/program/prescribed_motion.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "coupler/participant/body_rows.hpp"
#include "coupler/scene/eigen.hpp"

namespace cosim::fluid::program {
namespace {

constexpr std::array kind_names{"fixed", "constant", "sinusoidal"};

// q0 turned by the rotation vector w t (world frame): exp(w t / 2) q0.
Eigen::Quaterniond turned(const Eigen::Quaterniond& q0, const Eigen::Vector3d& w, double t) {
  const double angle = w.norm() * t;
  if (angle == 0) return q0;
  return (Eigen::Quaterniond(Eigen::AngleAxisd(angle, w.normalized())) * q0).normalized();
}

}  // namespace

std::vector<Motion> read_motions(const scene::Scene& scene, const scene::Reader& options, std::vector<Motion> start) {
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    const scene::Body& body = scene.bodies[b];
    start[b].kind = body.fixed ? Motion::Kind::fixed : Motion::Kind::constant;
    start[b].velocity = scene::to_eigen(body.velocity);
    start[b].angular_velocity = scene::to_eigen(body.angular_velocity);
  }
  if (!options.has("motion")) return start;
  const scene::Reader listed = options.map("motion");
  for (const std::string& name : listed.keys()) {
    std::size_t b = 0;
    while (b < scene.bodies.size() && scene.bodies[b].name != name) ++b;
    if (b == scene.bodies.size()) listed.fail(name, "not a body of the scene");
    const scene::Reader r = listed.map(name);
    Motion& m = start[b];
    m.kind = static_cast<Motion::Kind>(r.choice("type", kind_names));
    if (m.kind != Motion::Kind::constant) m.velocity = m.angular_velocity = Eigen::Vector3d::Zero();
    if (m.kind == Motion::Kind::sinusoidal) {
      m.amplitude = scene::to_eigen(r.vec3("amplitude", {0, 0, 0}));
      m.angular_amplitude = scene::to_eigen(r.vec3("angular_amplitude", {0, 0, 0}));
      m.frequency = r.number("frequency", scene::Range::above(0));
      if (m.amplitude.isZero(0) && m.angular_amplitude.isZero(0))
        r.fail("amplitude", "sinusoidal motion without amplitude or angular_amplitude: use type fixed");
    }
    r.finish();
  }
  listed.finish();
  return start;
}

std::vector<participant::PoseRow> poses_at(const std::vector<Motion>& motions, double t) {
  std::vector<participant::PoseRow> out;
  out.reserve(motions.size());
  for (const Motion& m : motions) {
    Eigen::Vector3d x = m.position + m.velocity * t, v = m.velocity, w = m.angular_velocity;
    Eigen::Quaterniond q = turned(m.orientation, m.angular_velocity, t);
    if (m.kind == Motion::Kind::sinusoidal) {
      const double omega = 2 * std::numbers::pi * m.frequency;
      const double phase = std::sin(omega * t), rate = omega * std::cos(omega * t);
      x = m.position + m.amplitude * phase;
      v = m.amplitude * rate;
      q = turned(m.orientation, m.angular_amplitude, phase);
      w = m.angular_amplitude * rate;
    }
    out.push_back({x, q, v, w});
  }
  return out;
}

}  // namespace cosim::fluid::program
