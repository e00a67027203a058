#include "tracker/mesh/box_part.hpp"

#include <stdexcept>
#include <string>

#include "tracker/mesh/part.hpp"

namespace cosim::tracker::mesh {
namespace {

// The box around the brick reaches this many hexahedra beyond it: the part's two ghost
// layers, and one more so that their faces have their neighbours as in the whole.
constexpr int kMargin = 3;

}  // namespace

Mesh box_part(const BoxSpec& spec, const std::array<int, 3>& lo, const std::array<int, 3>& hi,
              const std::function<int(Index)>& owner, int rank) {
  std::array<std::vector<double>, 3> nodes;
  std::array<int, 3> n{}, first{};
  BoxSpec around;
  around.tetrahedra = spec.tetrahedra;
  for (int a = 0; a < 3; ++a) {
    nodes[a] = axis_nodes(spec.axes[a]);
    n[a] = static_cast<int>(nodes[a].size()) - 1;
    if (!(0 <= lo[a] && lo[a] < hi[a] && hi[a] <= n[a]))
      throw std::invalid_argument("box part: hexahedra [" + std::to_string(lo[a]) + ", " + std::to_string(hi[a]) +
                                  ") on an axis of " + std::to_string(n[a]));
    int begin = lo[a] - kMargin, end = hi[a] + kMargin;
    if (spec.periodic[a] && (begin < 0 || end > n[a])) {
      begin = 0;  // the ghosts wrap around: the whole axis, linked as in the whole
      end = n[a];
      around.periodic[a] = true;
    }
    begin = std::max(begin, 0);
    end = std::min(end, n[a]);
    first[a] = begin;
    around.axes[a].nodes.assign(nodes[a].begin() + begin, nodes[a].begin() + end + 1);
  }
  const int per_hex = spec.tetrahedra ? 6 : 1;
  const std::array<int, 3> m{static_cast<int>(around.axes[0].nodes.size()) - 1,
                             static_cast<int>(around.axes[1].nodes.size()) - 1,
                             static_cast<int>(around.axes[2].nodes.size()) - 1};
  // A cell of the box around as the whole numbers it.
  const auto whole_cell = [&](Index c) {
    BoxCell cell = box_cell(c, m, per_hex);
    for (int a = 0; a < 3; ++a) cell.hex[a] += first[a];
    return box_cell_index(cell, n, per_hex);
  };
  Mesh part = extract_part(
      box_mesh(around), [&](Index c) { return owner(whole_cell(c)); }, rank);
  for (Index& g : part.global) g = whole_cell(g);
  part.whole_diagonal =
      Vec3(nodes[0].back() - nodes[0].front(), nodes[1].back() - nodes[1].front(), nodes[2].back() - nodes[2].front())
          .norm();
  return part;
}

}  // namespace cosim::tracker::mesh
