#include "tracker/csg/primitive.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace cosim::tracker::csg {

void require_invertible(const Eigen::Affine3d& affine) {
  const double det = affine.linear().determinant();
  if (!std::isfinite(det) || det == 0.0 || !affine.translation().allFinite())
    throw std::invalid_argument("csg: a placement or transform must be finite and invertible");
}

Primitive::Primitive(PrimitiveKind kind, const Eigen::Affine3d& placement) : kind_(kind), placement_(placement) {
  require_invertible(placement);
  place(Eigen::Isometry3d::Identity());
}

void Primitive::place(const Eigen::Isometry3d& pose) {
  const Eigen::Affine3d world = pose * placement_;
  origin_ = world.translation();
  to_canonical_ = world.linear().inverse();
}

Eigen::AlignedBox3d Primitive::bounds() const {
  if (kind_ == PrimitiveKind::half_space || kind_ == PrimitiveKind::cylinder) {
    const double inf = std::numeric_limits<double>::infinity();
    return {Eigen::Vector3d::Constant(-inf), Eigen::Vector3d::Constant(inf)};
  }
  // The canonical cube [-1, 1]^3 holds the unit ball and the box; its image is a
  // parallelepiped whose half extent along axis k is the row sum |M_k0| + |M_k1| + |M_k2|.
  const Eigen::Vector3d half = to_canonical_.inverse().cwiseAbs().rowwise().sum();
  return {origin_ - half, origin_ + half};
}

double Primitive::indicator(const Eigen::Vector3d& x) const {
  const Eigen::Vector3d p = to_canonical(x);
  switch (kind_) {
    case PrimitiveKind::half_space:
      return detail::half_space_indicator(p);
    case PrimitiveKind::ball:
      return detail::ball_indicator(p);
    case PrimitiveKind::cylinder:
      return detail::cylinder_indicator(p);
    case PrimitiveKind::box:
      return detail::box_indicator(p);
  }
  return 0.0;
}

// The world gradient of f(M (x - o)) is M^T grad f.
Eigen::Vector3d Primitive::normal(const Eigen::Vector3d& x) const {
  const Eigen::Vector3d p = to_canonical(x);
  Eigen::Vector3d g = Eigen::Vector3d::Zero();
  switch (kind_) {
    case PrimitiveKind::half_space:
      g = detail::half_space_gradient(p);
      break;
    case PrimitiveKind::ball:
      g = detail::ball_gradient(p);
      break;
    case PrimitiveKind::cylinder:
      g = detail::cylinder_gradient(p);
      break;
    case PrimitiveKind::box:
      g = detail::box_gradient(p);
      break;
  }
  return (to_canonical_.transpose() * g).normalized();
}

Chord Primitive::chord(const Eigen::Vector3d& x, const Eigen::Vector3d& v) const {
  const Eigen::Vector3d p = to_canonical(x);
  const Eigen::Vector3d u = to_canonical_ * v;
  switch (kind_) {
    case PrimitiveKind::half_space:
      return detail::half_space_chord(p, u);
    case PrimitiveKind::ball:
      return detail::ball_chord(p, u);
    case PrimitiveKind::cylinder:
      return detail::cylinder_chord(p, u);
    case PrimitiveKind::box:
      return detail::box_chord(p, u);
  }
  return Chord::empty();
}

bool Primitive::surface_may_meet(const Eigen::AlignedBox3d& box) const {
  Eigen::AlignedBox3d image;
  bool all_inside = true;
  for (int k = 0; k < 8; ++k) {
    const Eigen::Vector3d corner = box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(k));
    all_inside = all_inside && contains(corner);
    image.extend(to_canonical(corner));
  }
  if (all_inside) return false;
  const Eigen::Vector3d& lo = image.min();
  const Eigen::Vector3d& hi = image.max();
  const Eigen::Vector3d nearest = Eigen::Vector3d::Zero().cwiseMax(lo).cwiseMin(hi);  // to the origin
  switch (kind_) {
    case PrimitiveKind::half_space:
      return lo.z() <= 0.0;
    case PrimitiveKind::ball:
      return nearest.squaredNorm() <= 1.0;
    case PrimitiveKind::cylinder:
      return nearest.head<2>().squaredNorm() <= 1.0;
    case PrimitiveKind::box:
      return (lo.array() <= 1.0).all() && (hi.array() >= -1.0).all();
  }
  return true;
}

}  // namespace cosim::tracker::csg
