#include "fluid/ibm/marker_stencils.hpp"

namespace cosim::fluid {

namespace {

// Value c of marker l is number 3 id + c.
std::vector<PetscInt> value_ids(std::span<const ActiveMarker> markers) {
  std::vector<PetscInt> ids;
  for (const ActiveMarker& m : markers)
    for (std::size_t c = 0; c < 3; ++c) ids.push_back(static_cast<PetscInt>(3 * m.id + c));
  return ids;
}

}  // namespace

MarkerStencils::MarkerStencils(const Grid& grid, std::span<const ActiveMarker> markers, std::size_t total)
    : grid_(grid), sharing_(grid.comm(), value_ids(markers), static_cast<PetscInt>(3 * total)) {
  for (int c = 0; c < 3; ++c) owned_[static_cast<std::size_t>(c)] = grid.owned(grid.velocity_dm(c));
  const std::size_t n = markers.size();
  first_.assign(3 * n + 1, 0);
  for (std::size_t l = 0; l < n; ++l)
    for (std::size_t c = 0; c < 3; ++c) {
      first_[3 * l + c] = touches_.size();
      if (!markers[l].local[c]) continue;
      const Box& box = owned_[c];
      for_each_point(markers[l].stencil[c], box, [&](const Index& p, double w) {
        const std::ptrdiff_t offset =
            ((p[2] - box.lo[2]) * (box.hi[1] - box.lo[1]) + (p[1] - box.lo[1])) * (box.hi[0] - box.lo[0]) +
            (p[0] - box.lo[0]);
        touches_.push_back({offset, w, w / grid.face_volume(static_cast<int>(c), p)});
      });
    }
  first_[3 * n] = touches_.size();
}

std::array<PetscScalar*, 3> MarkerStencils::origins(const FaceArrays& field) const {
  std::array<PetscScalar*, 3> o{};
  for (std::size_t c = 0; c < 3; ++c) {
    const Box& b = owned_[c];
    if (b.hi[0] > b.lo[0] && b.hi[1] > b.lo[1] && b.hi[2] > b.lo[2]) o[c] = &field[c][b.lo[2]][b.lo[1]][b.lo[0]];
  }
  return o;
}

void MarkerStencils::spread(const FaceArrays& field, const std::vector<double>& g) const {
  const auto o = origins(field);
  for (std::size_t i = 0; i + 1 < first_.size(); ++i)
    if (g[i] != 0)
      for (std::size_t t = first_[i]; t < first_[i + 1]; ++t) o[i % 3][touches_[t].offset] += g[i] * touches_[t].spread;
}

void MarkerStencils::clear(const FaceArrays& field) const {
  const auto o = origins(field);
  for (std::size_t i = 0; i + 1 < first_.size(); ++i)
    for (std::size_t t = first_[i]; t < first_[i + 1]; ++t) o[i % 3][touches_[t].offset] = 0;
}

void MarkerStencils::interpolate(const FaceArrays& field, std::vector<double>& out) const {
  const auto o = origins(field);
  for (std::size_t i = 0; i + 1 < first_.size(); ++i) {
    double sum = 0;
    for (std::size_t t = first_[i]; t < first_[i + 1]; ++t) sum += touches_[t].weight * o[i % 3][touches_[t].offset];
    out[i] = sum;
  }
  sharing_.sum(out);
}

std::vector<double> MarkerStencils::diagonal() const {
  std::vector<double> d(first_.size() - 1, 0.0);
  for (std::size_t i = 0; i < d.size(); ++i)
    for (std::size_t t = first_[i]; t < first_[i + 1]; ++t) d[i] += touches_[t].weight * touches_[t].spread;
  sharing_.sum(d);
  return d;
}

}  // namespace cosim::fluid
