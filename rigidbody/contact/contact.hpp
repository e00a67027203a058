// What the narrow phase finds and the contact solvers work on.
#pragma once

#include <array>
#include <cstdint>

#include <Eigen/Core>

namespace cosim::rigidbody::contact {

// One point of contact between bodies a and b, in world coordinates. The normal points
// from a to b; `distance` is the signed gap along it (negative: penetration). Near
// contacts (small positive gap the next step could close) are included so the solver can
// keep them from closing too fast.
struct ContactPoint {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // midway between the two surfaces
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  double distance = 0.0;
  // Identifies the feature pair the point comes from (e.g. box vertex/face indices), so a
  // contact graph can match points across steps for warm starting; 0 when unknown.
  std::uint32_t feature = 0;
};

// All points between one pair of bodies (face contact between boxes has up to 4 per
// surface; the solver treats each point separately, with its own normal and friction
// impulses). A body in a container's corner touches up to three of its walls at once.
struct Manifold {
  static constexpr std::size_t kMaxPoints = 4;  // per surface
  static constexpr std::size_t kMaxSurfaces = 3;
  static constexpr std::size_t kCapacity = kMaxPoints * kMaxSurfaces;
  std::uint32_t a = 0;
  std::uint32_t b = 0;
  std::array<ContactPoint, kCapacity> points{};
  std::uint8_t count = 0;

  void add(const ContactPoint& p) {
    if (count < kCapacity) points[count++] = p;
  }
};

}  // namespace cosim::rigidbody::contact
