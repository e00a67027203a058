#include <tuple>
#include <type_traits>

#include "rigidbody/narrowphase/pairs.hpp"

namespace cosim::rigidbody::narrowphase {
namespace {

using namespace detail;

// Runs the pair function for (a, b), or for (b, a) and returns true (the caller flips the
// normals), falling back on the general mesh and convex paths.
template <class A, class B>
bool run(const A& a, const Pose& pa, const B& b, const Pose& pb, const Shape& sa, const Shape& sb, MeshMaps& maps,
         Candidates& out) {
  constexpr bool a_infinite = std::is_same_v<A, HalfSpace> || std::is_same_v<A, Container>;
  constexpr bool b_infinite = std::is_same_v<B, HalfSpace> || std::is_same_v<B, Container>;
  if constexpr (a_infinite && b_infinite) {
    // Both are fixed: nothing to solve.
  } else if constexpr (std::is_same_v<A, Container>) {
    container_pair(a, pa, sb, pb, out);
  } else if constexpr (std::is_same_v<B, Container>) {
    container_pair(b, pb, sa, pa, out);
    return true;
  } else if constexpr (requires { pair(a, pa, b, pb, out); }) {
    pair(a, pa, b, pb, out);
  } else if constexpr (requires { pair(b, pb, a, pa, out); }) {
    pair(b, pb, a, pa, out);
    return true;
  } else if constexpr (std::is_same_v<A, TriangleMesh>) {
    mesh_pair(a, pa, sb, pb, maps, out);
  } else if constexpr (std::is_same_v<B, TriangleMesh>) {
    mesh_pair(b, pb, sa, pa, maps, out);
    return true;
  } else {
    convex_pair(sa, pa, sb, pb, out);
  }
  return false;
}

// A canonical order of the two shapes (by kind, then position): GJK, EPA and the tie
// breaks of box-box depend on the order, and this makes a swapped call an exact mirror.
bool precedes(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb) {
  const auto key = [](const Shape& s, const Pose& p) {
    return std::tuple(s.index(), p.position().x(), p.position().y(), p.position().z());
  };
  return key(a, pa) < key(b, pb);
}

}  // namespace

MeshMaps::MeshMaps(double resolution) : resolution_(resolution) {}

bool collide(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, double margin, contact::Manifold& out,
             MeshMaps& maps) {
  if (precedes(b, pb, a, pa)) {
    const bool found = collide(b, pb, a, pa, margin, out, maps);
    for (int i = 0; i < out.count; ++i) out.points[i].normal = -out.points[i].normal;
    return found;
  }
  Candidates found;
  found.margin = margin;
  const bool swapped =
      std::visit([&](const auto& x, const auto& y) { return run(x, pa, y, pb, a, b, maps, found); }, a, b);
  if (!found.reduced) keep_spread(found.points);
  out.count = 0;
  for (auto& p : found.points) {
    if (swapped) p.normal = -p.normal;
    out.add(p);
  }
  return out.count > 0;
}

bool collide(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, double margin, contact::Manifold& out) {
  static MeshMaps maps;
  return collide(a, pa, b, pb, margin, out, maps);
}

}  // namespace cosim::rigidbody::narrowphase
