#include "tracker/program/output_grid.hpp"

#include "tracker/mesh/geometry.hpp"
#include "tracker/program/mixed_topology.hpp"

namespace cosim::tracker::program {
namespace {

std::vector<double> flat(const std::vector<Vec3>& points) {
  std::vector<double> out;
  out.reserve(3 * points.size());
  for (const Vec3& v : points) out.insert(out.end(), {v.x(), v.y(), v.z()});
  return out;
}

std::vector<double> patch_areas(const mesh::Mesh& mesh) {
  std::vector<double> area(mesh.patches.size(), 0.0);
  for (Index f = 0; f < mesh.face_count(); ++f)
    if (const Index code = mesh.faces[static_cast<std::size_t>(f)].neighbour; code < 0)
      area[static_cast<std::size_t>(mesh::patch_of(code))] += mesh::area_vector(mesh, f).norm();
  return area;
}

}  // namespace

OutputGrid output_grid(const mesh::BoxSpec& box) {
  field::RectilinearGrid nodes;
  std::array<double, 3> length{};
  for (int a = 0; a < 3; ++a) {
    nodes.nodes[a] = mesh::axis_nodes(box.axes[a]);
    length[a] = nodes.nodes[a].back() - nodes.nodes[a].front();
  }
  OutputGrid out;
  out.patches = {"x_min", "x_max", "y_min", "y_max", "z_min", "z_max"};
  for (int a = 0; a < 3; ++a) {
    const double side = box.periodic[a] ? 0.0 : length[(a + 1) % 3] * length[(a + 2) % 3];
    out.patch_area.insert(out.patch_area.end(), {side, side});
  }
  if (!box.tetrahedra) {
    out.grid = std::move(nodes);
    out.box = box;
    return out;
  }
  out.volume = step::cell_volumes(box);
  const mesh::Polyhedra cells = mesh::box_polyhedra(box);
  out.grid = field::PolyhedralGrid{flat(cells.vertices), mixed_topology(cells), out.volume.size()};
  return out;
}

OutputGrid output_grid(const mesh::Mesh& whole) {
  return {
      field::PolyhedralGrid{flat(whole.vertices), mixed_topology(whole), static_cast<std::size_t>(whole.cell_count())},
      whole.volume, std::nullopt, whole.patches, patch_areas(whole)};
}

OutputGrid output_grid(const step::Simulation& gas) {
  if (!gas.decomposition().ranks().lead()) throw std::logic_error("the output grid is rank 0's");
  return gas.setup().box ? output_grid(*gas.setup().box) : output_grid(*gas.setup().mesh);
}

}  // namespace cosim::tracker::program
