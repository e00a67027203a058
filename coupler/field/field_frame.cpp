#include "coupler/field/field_frame.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

namespace cosim::field {
namespace {

bool control(char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; }

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

// Every integer up to this is a float64, and a float64 beyond it may stand for several.
constexpr double kExactIntegers = 9007199254740992.0;  // 2^53

std::string attribute_problem(const PointSet& set, const PointAttribute& a) {
  const std::string what = "attribute " + quoted(a.name) + " of point set " + quoted(set.name);
  const std::size_t n = set.points.size() / 3;
  if (a.components < 1) return what + " has " + std::to_string(a.components) + " components";
  if (a.values.size() != n * static_cast<std::size_t>(a.components))
    return what + " has " + std::to_string(a.values.size()) + " values for " + std::to_string(n) + " points of " +
           std::to_string(a.components) + " components";
  if (a.integer)
    for (const double v : a.values)
      if (!(std::abs(v) <= kExactIntegers && v == std::floor(v)))  // NaN fails too
        return what + " holds " + std::to_string(v) + ", not a whole number within +-2^53";
  return {};
}

}  // namespace

bool dataset_name(const std::string& name) {
  // "a/b" would nest and "." is the group itself; NUL would end HDF5's C string too.
  return !name.empty() && name != "." &&
         std::none_of(name.begin(), name.end(), [](char c) { return c == '/' || control(c); });
}

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
    if (!dataset_name(s.name)) return "point set name " + quoted(s.name) + " cannot name an HDF5 dataset";
    if (!seen.insert(s.name).second) return "point set name " + quoted(s.name) + " appears twice";
    if (s.points.size() % 3 != 0)
      return "point set " + quoted(s.name) + " has " + std::to_string(s.points.size()) +
             " coordinates, not x y z triples";
    std::set<std::string> attributes;
    for (const PointAttribute& a : s.attributes) {
      if (!dataset_name(a.name))
        return "attribute name " + quoted(a.name) + " of point set " + quoted(s.name) + " cannot name an HDF5 dataset";
      if (!attributes.insert(a.name).second)
        return "attribute name " + quoted(a.name) + " appears twice in point set " + quoted(s.name);
      if (std::string problem = attribute_problem(s, a); !problem.empty()) return problem;
    }
  }
  return {};
}

std::string block_problem(const CellBlock& b, const std::array<std::size_t, 3>& cells,
                          const std::vector<CellField>& fields) {
  std::size_t n = 1;
  for (std::size_t a = 0; a < 3; ++a) {
    if (!(b.lo[a] <= b.hi[a] && b.hi[a] <= cells[a]))
      return "a block of cells [" + std::to_string(b.lo[a]) + ", " + std::to_string(b.hi[a]) + ") along " + "xyz"[a] +
             ", where the grid has " + std::to_string(cells[a]);
    n *= b.hi[a] - b.lo[a];
  }
  if (b.fields.size() != fields.size()) return "a block of " + std::to_string(b.fields.size()) + " fields";
  for (std::size_t k = 0; k < fields.size(); ++k) {
    const CellField& f = b.fields[k];
    if (f.name != fields[k].name || f.components != fields[k].components ||
        f.values.size() != n * static_cast<std::size_t>(f.components))
      return "a block's field " + f.name + " (" + std::to_string(f.values.size()) + " values) for field " +
             fields[k].name + " of " + std::to_string(fields[k].components) + " components on " + std::to_string(n) +
             " cells";
  }
  return {};
}

void place(const CellBlock& b, const std::array<std::size_t, 3>& cells, std::vector<CellField>& whole) {
  std::vector<CellField> layout;
  for (const CellField& f : whole) {
    if (f.values.size() != cells[0] * cells[1] * cells[2] * static_cast<std::size_t>(f.components))
      throw std::invalid_argument("place: field " + f.name + " does not hold the whole grid");
    layout.push_back({f.name, f.components, {}});
  }
  if (const std::string problem = block_problem(b, cells, layout); !problem.empty())
    throw std::invalid_argument("place: " + problem);
  for (std::size_t k = 0; k < whole.size(); ++k) {
    const auto width = static_cast<std::size_t>(whole[k].components);
    const std::size_t row = width * (b.hi[0] - b.lo[0]);
    const double* from = b.fields[k].values.data();
    for (std::size_t z = b.lo[2]; z < b.hi[2]; ++z)
      for (std::size_t y = b.lo[1]; y < b.hi[1]; ++y, from += row)
        std::copy_n(
            from, row,
            whole[k].values.begin() + static_cast<std::ptrdiff_t>(width * ((z * cells[1] + y) * cells[0] + b.lo[0])));
  }
}

}  // namespace cosim::field
