#pragma once

#include <Eigen/Geometry>

#include "tracker/csg/chord.hpp"

namespace cosim::tracker::csg {

// Each primitive is a canonical convex solid mapped by an invertible affine placement, so
// scaled, sheared and rotated variants (ellipsoids, elliptic cylinders, parallelepipeds) cost
// nothing extra: a line maps to a line with the same time parameter, so chords computed in
// the canonical frame are the world chords.
//   half_space: z <= 0            indicator z
//   ball:       |x| <= 1          indicator |x|^2 - 1
//   cylinder:   x^2 + y^2 <= 1    indicator x^2 + y^2 - 1   (infinite along z)
//   box:        |x_i| <= 1        indicator max_i |x_i| - 1
enum class PrimitiveKind { half_space, ball, cylinder, box };

// Convention everywhere: the indicator f is negative strictly inside, positive outside; the
// surface f = 0 counts as outside. The normal is grad f, made unit: it points outward.
class Primitive {
 public:
  // placement maps the canonical frame to the object frame; it must be invertible.
  Primitive(PrimitiveKind kind, const Eigen::Affine3d& placement);

  PrimitiveKind kind() const { return kind_; }
  const Eigen::Affine3d& placement() const { return placement_; }

  // Follows the object to its new pose (object frame to world).
  void place(const Eigen::Isometry3d& pose);

  double indicator(const Eigen::Vector3d& x) const;
  bool contains(const Eigen::Vector3d& x) const { return indicator(x) < 0.0; }
  Eigen::Vector3d normal(const Eigen::Vector3d& x) const;
  Chord chord(const Eigen::Vector3d& x, const Eigen::Vector3d& v) const;
  // Whether the surface may pass through the box: false only when the box is certainly
  // wholly inside (all corners are, and the primitive is convex) or wholly outside (its
  // image in the canonical frame, enlarged to an axis-aligned box, misses the solid).
  bool surface_may_meet(const Eigen::AlignedBox3d& box) const;
  // A box holding the whole solid: the image of the canonical cube for balls and boxes,
  // unbounded for half-spaces and cylinders. A quick reject before surface_may_meet.
  Eigen::AlignedBox3d bounds() const;

 private:
  // The canonical frame keeps its origin apart from the matrix so that points near the
  // primitive are differenced before they are scaled: M (x - o) loses no digits to a large
  // translation, M x + b would.
  Eigen::Vector3d to_canonical(const Eigen::Vector3d& x) const { return to_canonical_ * (x - origin_); }

  PrimitiveKind kind_;
  Eigen::Affine3d placement_;
  Eigen::Vector3d origin_;
  Eigen::Matrix3d to_canonical_;
};

// Throws std::invalid_argument unless the affine map is finite and invertible.
void require_invertible(const Eigen::Affine3d& affine);

namespace detail {
// The canonical solids, one file each.
double half_space_indicator(const Eigen::Vector3d& p);
Eigen::Vector3d half_space_gradient(const Eigen::Vector3d& p);
Chord half_space_chord(const Eigen::Vector3d& p, const Eigen::Vector3d& u);
double ball_indicator(const Eigen::Vector3d& p);
Eigen::Vector3d ball_gradient(const Eigen::Vector3d& p);
Chord ball_chord(const Eigen::Vector3d& p, const Eigen::Vector3d& u);
double cylinder_indicator(const Eigen::Vector3d& p);
Eigen::Vector3d cylinder_gradient(const Eigen::Vector3d& p);
Chord cylinder_chord(const Eigen::Vector3d& p, const Eigen::Vector3d& u);
double box_indicator(const Eigen::Vector3d& p);
Eigen::Vector3d box_gradient(const Eigen::Vector3d& p);
Chord box_chord(const Eigen::Vector3d& p, const Eigen::Vector3d& u);
}  // namespace detail

}  // namespace cosim::tracker::csg
