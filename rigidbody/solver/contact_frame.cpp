#include "rigidbody/solver/contact_frame.hpp"

#include <algorithm>
#include <cmath>

namespace cosim::rigidbody::solver {

namespace {

Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& r) {
  Eigen::Matrix3d m;
  m << 0, -r.z(), r.y(), r.z(), 0, -r.x(), -r.y(), r.x(), 0;
  return m;
}

// Change of point velocity per unit impulse at offset r from the centre of mass.
Eigen::Matrix3d point_response(const Mobility& m, const Eigen::Vector3d& r) {
  const Eigen::Matrix3d rx = cross_matrix(r);
  return m.inverse_mass * Eigen::Matrix3d::Identity() - rx * m.inverse_inertia_matrix() * rx;
}

Eigen::Vector3d any_tangent(const Eigen::Vector3d& n) {
  const Eigen::Vector3d helper = std::abs(n.x()) < 0.57735 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  return n.cross(helper).normalized();
}

}  // namespace

Mobility Mobility::of(double inverse_mass, const Eigen::Matrix3d& m) {
  return {inverse_mass, {m(0, 0), m(1, 1), m(2, 2), m(0, 1), m(0, 2), m(1, 2)}};
}

Eigen::Matrix3d Mobility::inverse_inertia_matrix() const {
  const std::array<double, 6>& m = inverse_inertia;
  Eigen::Matrix3d out;
  out << m[0], m[3], m[4], m[3], m[1], m[5], m[4], m[5], m[2];
  return out;
}

std::vector<Mobility> mobilities(std::span<const dynamics::BodyState> states,
                                 std::span<const dynamics::BodyInertia> inertias) {
  std::vector<Mobility> out(states.size());
  for (std::size_t i = 0; i < states.size(); ++i)
    out[i] = Mobility::of(inertias[i].inverse_mass, inertias[i].inverse_inertia_world(states[i].orientation));
  return out;
}

Eigen::Matrix3d ContactFrame::local_response(std::span<const Mobility> m) const {
  return basis * (point_response(m[a], ra) + point_response(m[b], rb)) * basis.transpose();
}

ContactFrame make_frame(const contact::PairContacts& m, const contact::ContactPoint& p,
                        std::span<const dynamics::BodyState> states) {
  ContactFrame f;
  f.a = m.a;
  f.b = m.b;
  f.ra = p.position - states[m.a].position;
  f.rb = p.position - states[m.b].position;
  const Eigen::Vector3d n = p.normal.normalized();
  const Eigen::Vector3d v = f.relative_velocity(states);
  const Eigen::Vector3d slip = v - v.dot(n) * n;
  // Relative threshold: a slip at round-off level would give a random direction.
  const bool sliding = slip.norm() > 1e-9 * std::max(1.0, v.norm());
  const Eigen::Vector3d t1 = sliding ? Eigen::Vector3d(slip.normalized()) : any_tangent(n);
  f.basis.row(0) = n;
  f.basis.row(1) = t1;
  f.basis.row(2) = n.cross(t1);
  return f;
}

}  // namespace cosim::rigidbody::solver
