#include "output/field_frame.hpp"

#include <algorithm>
#include <set>

namespace cosim::output {
namespace {

bool control(char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; }

// An HDF5 link name ("a/b" would nest, "." is the group itself) that is also an XDMF grid
// name: XML 1.0 has no way to hold control characters (NUL would end HDF5's C string too).
bool point_set_name(const std::string& name) {
  return !name.empty() && name != "." && std::none_of(name.begin(), name.end(), [](char c) {
    return c == '/' || control(c);
  });
}

// Quoted, with control characters shown as '?' so that the message stays one readable line.
std::string quoted(std::string name) {
  std::replace_if(name.begin(), name.end(), control, '?');
  return "'" + name + "'";
}

std::string topology_problem(const PolyhedralGrid& g) {
  if (g.cells == 0) return "a polyhedral grid without cells";
  if (g.vertices.size() % 3 != 0) return std::to_string(g.vertices.size()) + " vertex coordinates, not x y z triples";
  const auto vertices = static_cast<std::int64_t>(g.vertices.size() / 3);
  const auto& t = g.topology;
  const std::size_t end = t.size();
  std::size_t at = 0, cells = 0;
  // Each entry is read only after checking it exists, so a truncated topology is named as such.
  const auto truncated = [&] { return "the topology ends inside cell " + std::to_string(cells); };
  for (; at < end; ++cells) {
    const std::string cell = "cell " + std::to_string(cells) + " of the topology";
    if (t[at] != kXdmfPolyhedron) return cell + " has type " + std::to_string(t[at]) + ", not Polyhedron (16)";
    if (++at == end) return truncated();
    const std::int64_t faces = t[at++];
    if (faces < 4) return cell + " has " + std::to_string(faces) + " faces";
    for (std::int64_t f = 0; f < faces; ++f) {
      if (at == end) return truncated();
      const std::int64_t n = t[at++];
      if (n < 3) return cell + " has a face of " + std::to_string(n) + " vertices";
      if (n > static_cast<std::int64_t>(end - at)) return truncated();
      for (std::int64_t k = 0; k < n; ++k, ++at)
        if (t[at] < 0 || t[at] >= vertices)
          return cell + " names vertex " + std::to_string(t[at]) + " of " + std::to_string(vertices);
    }
  }
  if (cells != g.cells)
    return "the topology holds " + std::to_string(cells) + " cells, the grid says " + std::to_string(g.cells);
  return {};
}

}  // namespace

std::size_t cell_count(const Grid& grid) {
  if (const auto* p = std::get_if<PolyhedralGrid>(&grid)) return p->cells;
  const auto n = std::get<RectilinearGrid>(grid).cells();
  return n[0] * n[1] * n[2];
}

std::string grid_problem(const Grid& grid) {
  if (const auto* p = std::get_if<PolyhedralGrid>(&grid)) return topology_problem(*p);
  for (const auto& nodes : std::get<RectilinearGrid>(grid).nodes)
    if (nodes.size() < 2) return "an axis with fewer than 2 nodes";
  return {};
}

std::string point_sets_problem(const std::vector<PointSet>& sets) {
  std::set<std::string> seen;
  for (const PointSet& s : sets) {
    if (!point_set_name(s.name)) return "point set name " + quoted(s.name) + " cannot name an HDF5 dataset";
    if (!seen.insert(s.name).second) return "point set name " + quoted(s.name) + " appears twice";
    if (s.points.size() % 3 != 0)
      return "point set " + quoted(s.name) + " has " + std::to_string(s.points.size()) +
             " coordinates, not x y z triples";
  }
  return {};
}

}  // namespace cosim::output
