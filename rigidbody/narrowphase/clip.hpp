// Internal: contact points between two flat features (faces, segments) by clipping, the
// manifold step shared by box-box (faces) and the general convex path (any features).
#pragma once

#include <cstdint>
#include <vector>

#include "rigidbody/narrowphase/candidates.hpp"

namespace cosim::rigidbody::narrowphase::detail {

// A convex polygon (vertices in order, either winding), a segment (2 points) or a point.
using Polygon = std::vector<Vec3>;

// Unit normal of a face's plane, either sign (Newell's sum, relative to the first vertex so
// that far-off coordinates do not cost precision).
Vec3 face_normal(const Polygon& face);

// Sutherland-Hodgman against the half-space direction . (x - origin) <= limit.
Polygon clip(const Polygon& polygon, const Vec3& origin, const Vec3& direction, double limit);

// A shape's feature facing the other shape: its points (world) and an id that stays the
// same while the same face, edge or vertex faces it, for the contact points' feature ids.
struct Feature {
  Polygon points;
  std::uint32_t id = 0;
};

// Adds the contact points of feature a of shape a and feature b of shape b along the unit
// normal n (from a to b): the reference feature (the face more nearly normal to n, else a
// segment parallel to the other) bounds the incident one by side planes that contain n,
// and each clipped point is paired along n with the reference feature's plane. Only
// face-face, face-segment and parallel segments give points (`out` drops those beyond its
// margin); a point feature or crossing segments give none.
void clip_features(const Feature& a, const Feature& b, const Vec3& n, Candidates& out);

}  // namespace cosim::rigidbody::narrowphase::detail
