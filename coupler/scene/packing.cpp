#include "coupler/scene/packing.hpp"

#include "coupler/scene/cell_grid.hpp"
#include "coupler/scene/free_cells.hpp"

namespace cosim::scene {

std::vector<Vec3> lattice(const std::array<LatticeAxis, 3>& axes, const Vec3& jitter, Uniform& random) {
  std::vector<Vec3> centres;
  centres.reserve(static_cast<std::size_t>(axes[0].count) * axes[1].count * axes[2].count);
  for (int k = 0; k < axes[2].count; ++k)
    for (int j = 0; j < axes[1].count; ++j)
      for (int i = 0; i < axes[0].count; ++i) {
        const std::array<int, 3> at{i, j, k};
        Vec3 c{};
        for (int a = 0; a < 3; ++a) c[a] = axes[a].first + at[a] * axes[a].step + random(-jitter[a], jitter[a]);
        centres.push_back(c);
      }
  return centres;
}

std::vector<Vec3> random_addition(const Solid& body, const Domain& centres, std::size_t count,
                                  std::span<const Solid> obstacles, const std::function<double(const Vec3&)>& room,
                                  int attempts, Uniform& random) {
  // Cells one body wide: a query looks at no more than 2 x 2 x 2 cells.
  CellGrid grid(2 * body.radius);
  // Free cells an eighth of a body wide: small enough that one body rules out most cells
  // it reaches into, few enough (about 900 a body at solid fraction 0.3, 7 MB for 1000
  // bodies) to be cheap.
  FreeCells free(centres, 0.25 * body.radius);
  for (const Solid& o : obstacles) {
    grid.add(o);
    free.exclude(body, o);
  }
  free.keep_within(body, room);
  std::vector<Vec3> placed;
  placed.reserve(count);
  for (int refused = 0; placed.size() < count && refused < attempts && !free.empty();) {
    Solid s = body;
    s.centre = free.draw(random);
    if (room(s.centre) < body.radius || grid.first_overlap(s)) {
      ++refused;
      continue;
    }
    grid.add(s);
    free.exclude(body, s);
    placed.push_back(s.centre);
    refused = 0;
  }
  return placed;
}

}  // namespace cosim::scene
