// Contact points between two shapes: the narrow phase of the rigid-body simulator.
#pragma once

#include <memory>
#include <mutex>
#include <unordered_map>

#include "rigidbody/contact/contact.hpp"
#include "geometry/distance_map.hpp"
#include "geometry/shape.hpp"

namespace cosim::rigidbody::narrowphase {

// Distance maps of triangle meshes (body frame), built on first use and kept as long as
// the cache lives. Entries are keyed by the mesh's shared data, which the cache keeps
// alive, so copies of one mesh share one map and a key is never reused. Thread-safe.
class MeshMaps {
 public:
  // Grid spacing = bounding radius / resolution; the map's error bound is
  // (sqrt(3)/2) spacing (see geometry/distance_map.hpp).
  explicit MeshMaps(double resolution = 32.0);

  const geometry::DistanceMap& get(const geometry::TriangleMesh& mesh);
  double resolution() const { return resolution_; }

 private:
  struct Entry {
    geometry::TriangleMesh mesh;  // keeps the key alive
    std::unique_ptr<const geometry::DistanceMap> map;
  };
  double resolution_;
  std::mutex mutex_;
  std::unordered_map<const void*, Entry> entries_;
};

// Fills `out.points` / `out.count` (not out.a, out.b) with the contact points of shape a
// at pose pa and shape b at pose pb whose signed distance is at most `margin` (near
// contacts included), and returns whether there are any. Each point is midway between the
// surfaces, its normal points from a to b, and swapping a and b gives the same points
// with flipped normals. Every pair gives a full manifold (up to 4 points): general convex
// pairs clip the features facing each other along the GJK / libccd EPA normal. Two
// half-spaces never collide.
bool collide(const geometry::Shape& a, const geometry::Pose& pa, const geometry::Shape& b, const geometry::Pose& pb,
             double margin, contact::Manifold& out, MeshMaps& maps);

// The same with a process-wide MeshMaps of default resolution.
bool collide(const geometry::Shape& a, const geometry::Pose& pa, const geometry::Shape& b, const geometry::Pose& pb,
             double margin, contact::Manifold& out);

}  // namespace cosim::rigidbody::narrowphase
