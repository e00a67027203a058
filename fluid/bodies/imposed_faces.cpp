#include "fluid/bodies/imposed_faces.hpp"

namespace cosim::fluid::bodies {

using grid::Box;
using grid::Grid;
using grid::Index;

namespace {
bool inside(const Box& b, const Index& p) {
  for (int d = 0; d < 3; ++d)
    if (p[d] < b.lo[d] || p[d] >= b.hi[d]) return false;
  return true;
}
}  // namespace

ImposedFaces::ImposedFaces(const Grid& grid) : grid_(grid) {
  for (int c = 0; c < 3; ++c) {
    const Box b = grid.ghosted(grid.velocity_dm(c));
    ghosted_[static_cast<std::size_t>(c)] = b;
    owned_box_[static_cast<std::size_t>(c)] = grid.owned(grid.velocity_dm(c));
    mask_[static_cast<std::size_t>(c)].assign(
        static_cast<std::size_t>((b.hi[0] - b.lo[0]) * (b.hi[1] - b.lo[1]) * (b.hi[2] - b.lo[2])), 0);
  }
}

std::size_t ImposedFaces::offset(int c, const Index& p) const {
  const Box& b = ghosted_[static_cast<std::size_t>(c)];
  return static_cast<std::size_t>((p[0] - b.lo[0]) +
                                  (b.hi[0] - b.lo[0]) * ((p[1] - b.lo[1]) + (b.hi[1] - b.lo[1]) * (p[2] - b.lo[2])));
}

// Only the entries set last time are reset, so a rebuild costs what the bodies cover.
void ImposedFaces::clear() {
  for (int c = 0; c < 3; ++c) {
    const auto k = static_cast<std::size_t>(c);
    for (const Index& p : seen_[k]) mask_[k][offset(c, p)] = 0;
    previous_[k].swap(seen_[k]);
    seen_[k].clear();
    owned_[k].clear();
  }
}

void ImposedFaces::add(int c, const Index& p, double value) {
  const auto k = static_cast<std::size_t>(c);
  if (grid_.on_boundary(c, p)) return;  // the domain boundary condition rules there
  auto& flag = mask_[k][offset(c, p)];
  const bool mine = inside(owned_box_[k], p);
  if (flag) {  // overlapping bodies: the later one's velocity wins
    if (mine)
      for (ImposedFace& f : owned_[k])
        if (f.at == p) f.value = value;
    return;
  }
  flag = 1;
  seen_[k].push_back(p);
  if (mine) owned_[k].push_back({p, value});
}

void ImposedFaces::finish() {
  int changed = seen_ != previous_ ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &changed, 1, MPI_INT, MPI_MAX, grid_.comm());
  if (changed) ++generation_;
}

}  // namespace cosim::fluid::bodies
