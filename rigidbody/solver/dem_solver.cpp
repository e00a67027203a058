#include "rigidbody/solver/dem_solver.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <ostream>
#include <vector>

#include "rigidbody/solver/contact_frame.hpp"

namespace cosim::rigidbody::solver {

double damping_ratio(double restitution) {
  if (restitution <= 0.0) return 1.0;
  const double l = std::log(restitution);
  return -l / std::sqrt(std::numbers::pi * std::numbers::pi + l * l);
}

DemReport solve_dem(const ContactScene& scene, std::span<CachedContact> memory, const DemOptions& options) {
  const double dt = scene.dt;
  DemReport report;
  report.iterations = 1;
  std::vector<ContactFrame> frames;
  std::vector<Eigen::Vector3d> forces;

  for (std::size_t i = 0; i < scene.contacts.pairs.size(); ++i) {
    const contact::PairContacts& m = scene.contacts.pairs[i];
    const Material& material = scene.materials[i];
    // Translational reduced mass, the usual DEM choice (rotation does not soften the spring).
    const double inverse_mass = scene.mobility[m.a].inverse_mass + scene.mobility[m.b].inverse_mass;
    if (inverse_mass == 0.0) continue;
    const double mass = 1.0 / inverse_mass;
    const double zeta = damping_ratio(material.restitution);
    for (std::uint32_t k = m.first; k < m.first + m.count; ++k) {
      const contact::ContactPoint& p = scene.contacts.points[k];
      CachedContact& remembered = memory[k];
      const double overlap = -p.distance;
      if (overlap <= 0.0) {
        remembered = {};
        continue;
      }
      const ContactFrame frame = make_frame(m, p, scene.states);
      const Eigen::Vector3d n = frame.basis.row(0);
      const Eigen::Vector3d v = frame.relative_velocity(scene.states);
      const double vn = v.dot(n);
      const Eigen::Vector3d vt = v - vn * n;

      // Hertz: the spring's local stiffness dF/d(delta) sets damping and time scale.
      const bool hertz = options.law == NormalLaw::hertz;
      const double root = std::sqrt(overlap);
      const double kn = hertz ? 1.5 * options.normal_stiffness * root : options.normal_stiffness;
      const double spring = hertz ? options.normal_stiffness * overlap * root : kn * overlap;
      const double kt = options.tangential_stiffness_ratio * kn;
      // Damping on the end-of-step velocity (linearly implicit, closed form for the
      // scalar): the velocity already holds this step's gravity kick, which an explicit
      // dashpot would push against, shifting the rest overlap by c g dt / k. The dashpot
      // may pull near the end of a contact: that is what the restitution formula assumes
      // (cutting it off turns e = 0.3 into about 0.4).
      const double cn = 2.0 * zeta * std::sqrt(mass * kn);
      const double vn_end = (vn + dt * spring / mass) / (1.0 + dt * cn / mass);
      const double fn = spring - cn * vn_end;
      report.stable_dt = std::min(report.stable_dt, 2.0 / std::sqrt(kn / mass) / options.safety);

      // Turn the old spring into the new tangent plane, keeping its length.
      const double length = remembered.tangential.norm();
      Eigen::Vector3d stretch = remembered.tangential - remembered.tangential.dot(n) * n;
      if (stretch.norm() > 0.0) stretch *= length / stretch.norm();
      stretch += dt * vt;
      Eigen::Vector3d ft = -kt * stretch - 2.0 * zeta * std::sqrt(mass * kt) * vt;
      const double cap = material.friction * std::max(0.0, fn);
      if (ft.norm() > cap) {
        ft *= cap / ft.norm();
        stretch = -ft / kt;  // sliding: the spring holds exactly the Coulomb force
      }
      remembered = {.normal = dt * fn, .tangential = stretch};
      frames.push_back(frame);
      forces.push_back(fn * n + ft);
    }
  }
  // Forces from the velocities at the start of the step, applied together: the result
  // does not depend on the order of the contacts.
  for (std::size_t i = 0; i < frames.size(); ++i) frames[i].apply(dt * forces[i], scene.states, scene.mobility);

  if (dt > report.stable_dt && options.log)
    *options.log << "cosim DEM: dt = " << dt << " s exceeds the stable estimate " << report.stable_dt
                 << " s (2/omega / " << options.safety << ")\n";
  return report;
}

}  // namespace cosim::rigidbody::solver
