// Internal: one function per implemented (a, b) pair of shape kinds. Each adds to the
// candidates the points within their margin, with normals from a to b; collide.cpp calls
// the pair in either order and flips the normals when it had to swap.
#pragma once

#include <concepts>

#include "geometry/shape.hpp"
#include "rigidbody/narrowphase/candidates.hpp"
#include "rigidbody/narrowphase/narrowphase.hpp"

namespace cosim::rigidbody::narrowphase::detail {

using geometry::Box;
using geometry::Capsule;
using geometry::Container;
using geometry::ConvexHull;
using geometry::Cylinder;
using geometry::Ellipsoid;
using geometry::HalfSpace;
using geometry::Pose;
using geometry::Shape;
using geometry::Sphere;
using geometry::TriangleMesh;

void pair(const Sphere& a, const Pose& pa, const Sphere& b, const Pose& pb, Candidates& out);

// A sphere against any bounded convex shape is the shape's exact closest point to the
// centre (box, cylinder, capsule analytic; ellipsoid by Eberly's root; hull by faces).
template <class Convex>
requires(std::same_as<Convex, Box> || std::same_as<Convex, Cylinder> || std::same_as<Convex, Capsule> ||
         std::same_as<Convex, Ellipsoid> || std::same_as<Convex, ConvexHull>) void pair(const Convex& a, const Pose& pa,
                                                                                        const Sphere& b, const Pose& pb,
                                                                                        Candidates& out) {
  const auto c = a.closest(pa.to_body(pb.position()));
  const Vec3 normal = pa.direction_to_world(c.normal);
  out.add(pa.to_world(c.point), normal, c.distance - b.radius(), 0);
}

void pair(const Capsule& a, const Pose& pa, const Capsule& b, const Pose& pb, Candidates& out);
void pair(const Box& a, const Pose& pa, const Box& b, const Pose& pb, Candidates& out);

void pair(const HalfSpace& a, const Pose& pa, const Sphere& b, const Pose& pb, Candidates& out);
void pair(const HalfSpace& a, const Pose& pa, const Capsule& b, const Pose& pb, Candidates& out);
void pair(const HalfSpace& a, const Pose& pa, const Box& b, const Pose& pb, Candidates& out);
void pair(const HalfSpace& a, const Pose& pa, const Cylinder& b, const Pose& pb, Candidates& out);
void pair(const HalfSpace& a, const Pose& pa, const Ellipsoid& b, const Pose& pb, Candidates& out);
void pair(const HalfSpace& a, const Pose& pa, const ConvexHull& b, const Pose& pb, Candidates& out);
void pair(const HalfSpace& a, const Pose& pa, const TriangleMesh& b, const Pose& pb, Candidates& out);

// Any two bounded convex shapes: GJK distance, libccd EPA when they overlap, then the
// features facing each other along that normal clipped (clip.hpp, feature.hpp).
void convex_pair(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, Candidates& out);

// A bounded shape inside a container, against the container's exact distance.
void container_pair(const Container& a, const Pose& pa, const Shape& b, const Pose& pb, Candidates& out);

// A mesh against any bounded shape (another mesh included), through distance maps.
void mesh_pair(const TriangleMesh& a, const Pose& pa, const Shape& b, const Pose& pb, MeshMaps& maps, Candidates& out);

}  // namespace cosim::rigidbody::narrowphase::detail
