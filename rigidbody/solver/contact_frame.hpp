// The kinematics every contact solver shares: where a point sits on each body, how fast
// the bodies move relative to each other there, and how an impulse changes that.
#pragma once

#include <array>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "rigidbody/contact/contact_set.hpp"
#include "rigidbody/dynamics/body.hpp"

namespace cosim::rigidbody::solver {

// Inverse mass and world inverse inertia, evaluated once per step (orientation is fixed
// while the solver runs). The inverse inertia is symmetric and keeps its upper triangle:
// 56 bytes a body where the whole matrix took 80.
struct Mobility {
  double inverse_mass = 0.0;
  std::array<double, 6> inverse_inertia{};  // xx, yy, zz, xy, xz, yz

  // Of the matrix's upper triangle.
  static Mobility of(double inverse_mass, const Eigen::Matrix3d& inverse_inertia);
  Eigen::Matrix3d inverse_inertia_matrix() const;
  // I^-1 v, in the sweeps' every impulse (inline, as ContactFrame::apply).
  Eigen::Vector3d turn(const Eigen::Vector3d& v) const {
    const std::array<double, 6>& m = inverse_inertia;
    return {m[0] * v.x() + m[3] * v.y() + m[4] * v.z(), m[3] * v.x() + m[1] * v.y() + m[5] * v.z(),
            m[4] * v.x() + m[5] * v.y() + m[2] * v.z()};
  }
};

std::vector<Mobility> mobilities(std::span<const dynamics::BodyState> states,
                                 std::span<const dynamics::BodyInertia> inertias);

// A contact point between bodies a and b. Rows of `basis` are the normal (a to b) and
// two tangents; local vectors (velocity, impulse) are (normal, tangent1, tangent2).
struct ContactFrame {
  std::uint32_t a = 0;
  std::uint32_t b = 0;
  Eigen::Vector3d ra = Eigen::Vector3d::Zero();  // point relative to each centre of mass
  Eigen::Vector3d rb = Eigen::Vector3d::Zero();
  Eigen::Matrix3d basis = Eigen::Matrix3d::Identity();

  // Velocity of b relative to a at the point, world frame. Defined here, as apply(): the
  // sweeps call little else, and out of line the calls cost a granular step about a tenth
  // (bench/rigidbody_granular/README.md, "Where the time goes").
  Eigen::Vector3d relative_velocity(std::span<const dynamics::BodyState> s) const {
    return s[b].velocity + s[b].angular_velocity.cross(rb) - s[a].velocity - s[a].angular_velocity.cross(ra);
  }
  Eigen::Vector3d local_velocity(std::span<const dynamics::BodyState> states) const {
    return basis * relative_velocity(states);
  }
  // +impulse on b, -impulse on a (world frame).
  void apply(const Eigen::Vector3d& impulse, std::span<dynamics::BodyState> s, std::span<const Mobility> m) const {
    s[a].velocity -= m[a].inverse_mass * impulse;
    s[a].angular_velocity -= m[a].turn(ra.cross(impulse));
    s[b].velocity += m[b].inverse_mass * impulse;
    s[b].angular_velocity += m[b].turn(rb.cross(impulse));
  }
  void apply_local(const Eigen::Vector3d& local, std::span<dynamics::BodyState> states,
                   std::span<const Mobility> mobility) const {
    apply(basis.transpose() * local, states, mobility);
  }
  // Delassus block: change of local relative velocity per unit local impulse.
  Eigen::Matrix3d local_response(std::span<const Mobility> mobility) const;
};

// First tangent along `slip` when it has a tangential part (so the friction pyramid is
// aligned with the sliding direction and does not bias it), otherwise any.
ContactFrame make_frame(const contact::PairContacts& pair, const contact::ContactPoint& p,
                        std::span<const dynamics::BodyState> states);

}  // namespace cosim::rigidbody::solver
