#include "geometry/detail/mesh_topology.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <bit>
#include <cmath>
#include <map>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <unordered_map>

namespace cosim::geometry::detail {
namespace {

std::string text(const Eigen::Vector3d& v) {
  std::ostringstream s;
  s.precision(17);
  s << '(' << v.x() << ", " << v.y() << ", " << v.z() << ')';
  return s.str();
}

struct ExactKey {
  std::array<std::uint64_t, 3> bits;
  bool operator==(const ExactKey&) const = default;
};

struct ExactKeyHash {
  std::size_t operator()(const ExactKey& k) const {
    std::size_t h = 0;
    for (std::uint64_t b : k.bits) h = (h ^ b) * 0x100000001b3ull + 0x9e3779b97f4a7c15ull;
    return h;
  }
};

ExactKey key_of(const Eigen::Vector3d& v) {
  // Adding +0 turns -0 into +0, which compare equal but differ in bits.
  return {std::bit_cast<std::uint64_t>(v.x() + 0.0), std::bit_cast<std::uint64_t>(v.y() + 0.0),
          std::bit_cast<std::uint64_t>(v.z() + 0.0)};
}

struct HalfEdge {
  std::uint32_t lo, hi;  // vertex indices, lo < hi
  std::uint32_t triangle;
  std::uint8_t corner;  // the edge runs from corner to corner + 1
  bool forward;         // ... and from lo to hi
};

// Collects the first example and the count of each kind of bad edge for one message.
class EdgeProblems {
 public:
  void add(const char* kind, const std::string& example) {
    auto& [count, first] = problems_[kind];
    if (count++ == 0) first = example;
  }
  void throw_if_any() const {
    if (problems_.empty()) return;
    std::string message;
    for (const auto& [kind, entry] : problems_)
      message += (message.empty() ? "" : "; ") + std::to_string(entry.first) + " " + kind + ", e.g. " + entry.second;
    throw std::invalid_argument(message);
  }

 private:
  std::map<std::string, std::pair<std::size_t, std::string>> problems_;
};

double signed_volume(const std::vector<Eigen::Vector3d>& v, const std::vector<Triangle>& triangles,
                     const std::vector<std::uint32_t>& members) {
  const Eigen::Vector3d o = v[triangles[members.front()][0]];  // a nearby origin keeps the sum accurate
  double six_volume = 0.0;
  for (std::uint32_t t : members) {
    const Triangle& c = triangles[t];
    six_volume += (v[c[0]] - o).dot((v[c[1]] - o).cross(v[c[2]] - o));
  }
  return six_volume / 6.0;
}

// Generalised winding number of a closed component around q: +-1 inside, 0 outside.
double winding_number(const std::vector<Eigen::Vector3d>& v, const std::vector<Triangle>& triangles,
                      const std::vector<std::uint32_t>& members, const Eigen::Vector3d& q) {
  double solid_angle = 0.0;
  for (std::uint32_t t : members) {
    const Eigen::Vector3d a = v[triangles[t][0]] - q, b = v[triangles[t][1]] - q, c = v[triangles[t][2]] - q;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double numerator = a.dot(b.cross(c));
    const double denominator = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
    solid_angle += 2.0 * std::atan2(numerator, denominator);
  }
  return solid_angle / (4.0 * std::numbers::pi);
}

std::vector<std::vector<std::uint32_t>> components(const Neighbors& neighbors) {
  std::vector<std::vector<std::uint32_t>> result;
  std::vector<bool> seen(neighbors.size(), false);
  for (std::uint32_t start = 0; start < neighbors.size(); ++start) {
    if (seen[start]) continue;
    std::vector<std::uint32_t> members{start};
    seen[start] = true;
    for (std::size_t i = 0; i < members.size(); ++i)
      for (std::uint32_t n : neighbors[members[i]])
        if (!seen[n]) {
          seen[n] = true;
          members.push_back(n);
        }
    result.push_back(std::move(members));
  }
  return result;
}

}  // namespace

WeldedMesh weld(const std::vector<Eigen::Vector3d>& vertices, const std::vector<Triangle>& triangles) {
  WeldedMesh out;
  std::unordered_map<ExactKey, std::uint32_t, ExactKeyHash> index_of;
  std::vector<std::uint32_t> remap(vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    if (!vertices[i].allFinite()) throw std::invalid_argument("vertex " + std::to_string(i) + " is not finite");
    const auto [it, inserted] =
        index_of.try_emplace(key_of(vertices[i]), static_cast<std::uint32_t>(out.vertices.size()));
    if (inserted) out.vertices.push_back(vertices[i]);
    remap[i] = it->second;
  }
  out.merged_vertices = vertices.size() - out.vertices.size();
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    Triangle w;
    for (int k = 0; k < 3; ++k) {
      if (triangles[t][k] >= vertices.size())
        throw std::invalid_argument("triangle " + std::to_string(t) + " refers to vertex " +
                                    std::to_string(triangles[t][k]) + " of " + std::to_string(vertices.size()));
      w[k] = remap[triangles[t][k]];
    }
    if (w[0] == w[1] || w[1] == w[2] || w[2] == w[0])
      ++out.dropped_triangles;
    else
      out.triangles.push_back(w);
  }
  if (out.triangles.empty()) throw std::invalid_argument("the mesh has no triangles");
  return out;
}

void require_nondegenerate(const std::vector<Eigen::Vector3d>& v, const std::vector<Triangle>& triangles) {
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const Triangle& c = triangles[t];
    if ((v[c[1]] - v[c[0]]).cross(v[c[2]] - v[c[0]]).squaredNorm() == 0.0)
      throw std::invalid_argument("triangle " + std::to_string(t) + " has zero area: corners " + text(v[c[0]]) + ", " +
                                  text(v[c[1]]) + ", " + text(v[c[2]]) + " are collinear");
  }
}

Neighbors edge_neighbors(const std::vector<Eigen::Vector3d>& v, const std::vector<Triangle>& triangles) {
  std::vector<HalfEdge> edges;
  edges.reserve(3 * triangles.size());
  for (std::uint32_t t = 0; t < triangles.size(); ++t)
    for (std::uint8_t k = 0; k < 3; ++k) {
      const std::uint32_t a = triangles[t][k], b = triangles[t][(k + 1) % 3];
      edges.push_back({std::min(a, b), std::max(a, b), t, k, a < b});
    }
  std::sort(edges.begin(), edges.end(),
            [](const HalfEdge& x, const HalfEdge& y) { return std::tie(x.lo, x.hi) < std::tie(y.lo, y.hi); });

  Neighbors neighbors(triangles.size());
  EdgeProblems problems;
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i + 1;
    while (j < edges.size() && edges[j].lo == edges[i].lo && edges[j].hi == edges[i].hi) ++j;
    const HalfEdge& a = edges[i];
    const auto where = [&] { return "the edge " + text(v[a.lo]) + " - " + text(v[a.hi]); };
    if (j - i == 1) {
      problems.add("open edges (one triangle only: the mesh is not closed)", where());
    } else if (j - i > 2) {
      problems.add("non-manifold edges (more than two triangles)", where());
    } else if (a.forward == edges[i + 1].forward) {
      problems.add(
          "edges with inconsistent orientation (two triangles run the same way)",
          where() + " in triangles " + std::to_string(a.triangle) + " and " + std::to_string(edges[i + 1].triangle));
    } else {
      neighbors[a.triangle][a.corner] = edges[i + 1].triangle;
      neighbors[edges[i + 1].triangle][edges[i + 1].corner] = a.triangle;
    }
    i = j;
  }
  problems.throw_if_any();
  return neighbors;
}

std::vector<std::size_t> orient_outward(const std::vector<Eigen::Vector3d>& v, std::vector<Triangle>& triangles,
                                        const Neighbors& neighbors) {
  const auto parts = components(neighbors);
  std::vector<double> volumes;
  for (const auto& members : parts) {
    volumes.push_back(signed_volume(v, triangles, members));
    if (volumes.back() == 0.0)
      throw std::invalid_argument("a closed component encloses no volume (triangle " + std::to_string(members.front()) +
                                  ")");
  }
  std::vector<std::size_t> flipped;
  for (std::size_t a = 0; a < parts.size(); ++a) {
    int depth = 0;
    if (parts.size() > 1) {
      const Triangle& t = triangles[parts[a].front()];
      const Eigen::Vector3d q = (v[t[0]] + v[t[1]] + v[t[2]]) / 3.0;
      for (std::size_t b = 0; b < parts.size(); ++b)
        if (b != a && std::abs(winding_number(v, triangles, parts[b], q)) > 0.5) ++depth;
    }
    const bool cavity = depth % 2 == 1;
    if ((volumes[a] < 0.0) != cavity) {
      for (std::uint32_t t : parts[a]) std::swap(triangles[t][1], triangles[t][2]);
      flipped.push_back(parts[a].size());
    }
  }
  return flipped;
}

}  // namespace cosim::geometry::detail
