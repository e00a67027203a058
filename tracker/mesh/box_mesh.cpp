#include "tracker/mesh/box_mesh.hpp"

#include "tracker/mesh/assemble.hpp"
#include "tracker/mesh/element_faces.hpp"
#include "tracker/mesh/validate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>

namespace cosim::tracker::mesh {

std::vector<double> axis_nodes(const AxisSpacing& axis) {
  if (!axis.nodes.empty()) {
    if (axis.nodes.size() < 2) throw std::invalid_argument("box mesh: an axis needs at least two nodes");
    for (std::size_t i = 1; i < axis.nodes.size(); ++i)
      if (!(axis.nodes[i] > axis.nodes[i - 1]))
        throw std::invalid_argument("box mesh: axis nodes must increase (node " + std::to_string(i) + ")");
    return axis.nodes;
  }
  if (axis.cells < 1) throw std::invalid_argument("box mesh: cells per axis must be at least 1");
  if (!(axis.max > axis.min)) throw std::invalid_argument("box mesh: axis max must exceed min");
  if (!(axis.ratio > 0.0)) throw std::invalid_argument("box mesh: grading ratio must be positive");
  const int n = axis.cells;
  // Widths w_i = w_0 q^i with q^(n-1) = ratio.
  const double q = n > 1 ? std::pow(axis.ratio, 1.0 / (n - 1)) : 1.0;
  std::vector<double> nodes(n + 1);
  double width = 1.0, sum = 0.0;
  for (int i = 0; i < n; ++i, width *= q) {
    nodes[i] = sum;
    sum += width;
  }
  for (int i = 0; i < n; ++i) nodes[i] = axis.min + (axis.max - axis.min) * nodes[i] / sum;
  nodes[n] = axis.max;
  return nodes;
}

namespace {

// Hexahedron corners: bit 0 = +x, bit 1 = +y, bit 2 = +z. Faces counter-clockwise from
// outside, with their patch when on the box boundary.
constexpr int hex_faces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};

// Kuhn's six tetrahedra: the monotone paths from corner 0 to corner 7, one axis at a time.
constexpr int axis_orders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};

// Links the faces of the low side of `axis` (patch 2 axis) with those of the high side:
// partners have the same vertices once the high side's node index on the axis is taken as
// the low side's, an exact integer match whatever the split. `node` maps a vertex id to
// its node indices, `low_id` sets the axis index to 0.
template <class LowId>
void link_periodic(Mesh& mesh, int axis, double period, const LowId& low_id) {
  const Index low = 2 * axis, high = 2 * axis + 1;
  const auto key = [&](Index f) {
    std::vector<Index> ids;
    for (Index k = mesh.face_vertex_begin[f]; k < mesh.face_vertex_begin[f + 1]; ++k)
      ids.push_back(low_id(mesh.face_vertex_index[k]));
    std::sort(ids.begin(), ids.end());
    return ids;
  };
  std::map<std::vector<Index>, Index> high_faces;
  for (Index f = 0; f < mesh.face_count(); ++f)
    if (mesh.faces[f].neighbour == boundary_code(high)) high_faces.emplace(key(f), f);
  Vec3 up = Vec3::Zero();
  up[axis] = period;
  const auto up_shift = static_cast<Index>(mesh.shifts.size());
  mesh.shifts.push_back(up);   // from the low side into the high side's cells
  mesh.shifts.push_back(-up);  // and back
  for (Index f = 0; f < mesh.face_count(); ++f) {
    if (mesh.faces[f].neighbour != boundary_code(low)) continue;
    const auto it = high_faces.find(key(f));
    if (it == high_faces.end()) throw std::logic_error("box mesh: a periodic face without a partner");
    const Index g = it->second;
    mesh.faces[f] = {mesh.faces[f].normal, mesh.faces[f].point, mesh.cell_of_face(g), g, up_shift};
    mesh.faces[g] = {mesh.faces[g].normal, mesh.faces[g].point, mesh.cell_of_face(f), f, up_shift + 1};
  }
}

}  // namespace

BoxSpec cube(int cells, bool tetrahedra) {
  BoxSpec spec;
  for (AxisSpacing& axis : spec.axes) axis.cells = cells;
  spec.tetrahedra = tetrahedra;
  return spec;
}

Polyhedra box_polyhedra(const BoxSpec& spec) {
  std::array<std::vector<double>, 3> nodes;
  for (int k = 0; k < 3; ++k) nodes[k] = axis_nodes(spec.axes[k]);
  const int nx = static_cast<int>(nodes[0].size()), ny = static_cast<int>(nodes[1].size()),
            nz = static_cast<int>(nodes[2].size());
  // The faces' vertex lists are the longest array a mesh numbers (Index, 32 bits).
  const long long hexahedra = 1LL * (nx - 1) * (ny - 1) * (nz - 1), entries_per_hex = spec.tetrahedra ? 72 : 24;
  if (hexahedra * entries_per_hex > std::numeric_limits<Index>::max())
    throw std::invalid_argument("box mesh: " + std::to_string(hexahedra) + " hexahedra" +
                                (spec.tetrahedra ? " split into tetrahedra" : "") +
                                " are more than one mesh numbers in 32 bits: at most " +
                                std::to_string(std::numeric_limits<Index>::max() / entries_per_hex) +
                                " (on several ranks a rank's part, which more ranks make smaller)");

  Polyhedra poly;
  poly.source = "box mesh";
  poly.patches = {"x_min", "x_max", "y_min", "y_max", "z_min", "z_max"};
  poly.vertices.reserve(std::size_t(nx) * ny * nz);
  // The mesh keeps these arrays: sized once, without the slack of growing them.
  const auto cells = static_cast<std::size_t>(hexahedra) * (spec.tetrahedra ? 6 : 1);
  const std::size_t faces = 6 * static_cast<std::size_t>(hexahedra) * (spec.tetrahedra ? 4 : 1);
  poly.cell_faces.reserve(cells + 1);
  poly.face_vertex_begin.reserve(faces + 1);
  poly.face_patch.reserve(faces);
  poly.face_vertex_index.reserve(static_cast<std::size_t>(hexahedra * entries_per_hex));
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) poly.vertices.emplace_back(nodes[0][i], nodes[1][j], nodes[2][k]);

  for (int k = 0; k + 1 < nz; ++k)
    for (int j = 0; j + 1 < ny; ++j)
      for (int i = 0; i + 1 < nx; ++i) {
        const std::array<int, 3> cell{i, j, k}, last{nx - 2, ny - 2, nz - 2};
        std::array<Index, 8> corner;
        for (int b = 0; b < 8; ++b) corner[b] = (i + (b & 1)) + nx * ((j + (b >> 1 & 1)) + ny * (k + (b >> 2 & 1)));
        // Patch of the face with all coordinates at the box's min or max on axis a.
        const auto patch_on = [&](int axis, bool high) {
          return cell[axis] == (high ? last[axis] : 0) ? Index(2 * axis + (high ? 1 : 0)) : Index(-1);
        };
        if (!spec.tetrahedra) {
          for (int f = 0; f < 6; ++f)
            poly.add_face(
                {corner[hex_faces[f][0]], corner[hex_faces[f][1]], corner[hex_faces[f][2]], corner[hex_faces[f][3]]},
                patch_on(f / 2, f % 2 == 1));
          poly.end_cell();
          continue;
        }
        for (const auto& order : axis_orders) {
          std::array<int, 4> t{0, 1 << order[0], (1 << order[0]) | (1 << order[1]), 7};
          const Vec3 p0 = poly.vertices[corner[t[0]]], p1 = poly.vertices[corner[t[1]]],
                     p2 = poly.vertices[corner[t[2]]], p3 = poly.vertices[corner[t[3]]];
          // Odd permutations of the axes give left-handed corner orders.
          if ((p1 - p0).cross(p2 - p0).dot(p3 - p0) < 0.0) std::swap(t[1], t[2]);
          // A tetrahedron face lies on the box boundary iff its three corners share the
          // bit of an axis (all low or all high) and the cell touches that side.
          for (const auto& face : element_faces::tetrahedron) {
            Index patch = -1;
            for (int axis = 0; axis < 3 && patch < 0; ++axis) {
              const int bits = (t[face[0]] >> axis & 1) + (t[face[1]] >> axis & 1) + (t[face[2]] >> axis & 1);
              if (bits == 0) patch = patch_on(axis, false);
              if (bits == 3) patch = patch_on(axis, true);
            }
            poly.add_face({corner[t[face[0]]], corner[t[face[1]]], corner[t[face[2]]]}, patch);
          }
          poly.end_cell();
        }
      }
  return poly;
}

Mesh box_mesh(const BoxSpec& spec) {
  Mesh mesh = assemble(box_polyhedra(spec));
  std::array<std::vector<double>, 3> nodes;
  std::array<int, 3> n{};  // nodes per axis
  for (int a = 0; a < 3; ++a) {
    nodes[a] = axis_nodes(spec.axes[a]);
    n[a] = static_cast<int>(nodes[a].size());
  }
  const int nx = n[0], ny = n[1];
  for (int a = 0; a < 3; ++a) {
    if (!spec.periodic[a]) continue;
    link_periodic(mesh, a, nodes[a].back() - nodes[a].front(), [&](Index id) {
      std::array<Index, 3> ijk{id % nx, id / nx % ny, id / (nx * ny)};
      if (ijk[a] == n[a] - 1) ijk[a] = 0;
      return ijk[0] + nx * (ijk[1] + ny * ijk[2]);
    });
  }
  require_valid(mesh);
  return mesh;
}

}  // namespace cosim::tracker::mesh
