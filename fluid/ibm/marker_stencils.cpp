#include "fluid/ibm/marker_stencils.hpp"

#include <algorithm>

namespace cosim::fluid::ibm {

using grid::Box;
using grid::Grid;
using grid::Index;

namespace {

// Value c of marker l is number 3 id + c.
std::vector<PetscInt> value_ids(std::span<const ActiveMarker> markers) {
  std::vector<PetscInt> ids;
  for (const ActiveMarker& m : markers)
    for (std::size_t c = 0; c < 3; ++c) ids.push_back(static_cast<PetscInt>(3 * m.id + c));
  return ids;
}

}  // namespace

MarkerStencils::MarkerStencils(const Grid& grid, std::span<const ActiveMarker> markers, PetscInt roots)
    : grid_(grid), ids_(value_ids(markers)), sharing_(grid.comm(), ids_, roots) {
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

void MarkerStencils::interpolate(const FaceArrays& field, std::vector<double>& out) const {
  const auto o = origins(field);
  for (std::size_t i = 0; i + 1 < first_.size(); ++i) {
    double sum = 0;
    for (std::size_t t = first_[i]; t < first_[i + 1]; ++t) sum += touches_[t].weight * o[i % 3][touches_[t].offset];
    out[i] = sum;
  }
  sharing_.sum(out);
}

std::vector<MarkerStencils::Product> MarkerStencils::products(const MarkerStencils& spreading) const {
  const std::size_t values = first_.size() - 1;
  // The spreading's touches grouped by face: face f of component c is key base[c] + f, its
  // touches entries at[key] .. at[key + 1] - 1 of `by_face`.
  struct Spread {
    std::size_t value;
    double spread;
  };
  const std::vector<Touch>& spread = spreading.touches_;
  std::array<std::size_t, 4> base{};
  for (std::size_t c = 0; c < 3; ++c) {
    const Box& b = owned_[c];
    base[c + 1] = base[c] + static_cast<std::size_t>(
                                std::max<PetscInt>(0, (b.hi[0] - b.lo[0]) * (b.hi[1] - b.lo[1]) * (b.hi[2] - b.lo[2])));
  }
  const auto key = [&](std::size_t i, const Touch& t) { return base[i % 3] + static_cast<std::size_t>(t.offset); };
  std::vector<std::size_t> at(base[3] + 1, 0);
  for (std::size_t i = 0; i < values; ++i)
    for (std::size_t t = spreading.first_[i]; t < spreading.first_[i + 1]; ++t) ++at[key(i, spread[t])];
  for (std::size_t k = 1; k < at.size(); ++k) at[k] += at[k - 1];  // each face's end ...
  std::vector<Spread> by_face(spread.size());
  for (std::size_t i = values; i-- > 0;)
    for (std::size_t t = spreading.first_[i + 1]; t-- > spreading.first_[i];)
      by_face[--at[key(i, spread[t])]] = {i, spread[t].spread};  // ... becomes its start
  // Row i gathers its products in `row`, the columns it met in `met`.
  std::vector<double> row(values, 0.0);
  std::vector<char> seen(values, 0);
  std::vector<std::size_t> met;
  std::vector<Product> out;
  for (std::size_t i = 0; i < values; ++i) {
    for (std::size_t t = first_[i]; t < first_[i + 1]; ++t) {
      const std::size_t f = key(i, touches_[t]);
      const double w = touches_[t].weight;
      for (std::size_t k = at[f]; k < at[f + 1]; ++k) {
        const std::size_t j = by_face[k].value;
        if (!seen[j]) {
          seen[j] = 1;
          met.push_back(j);
        }
        row[j] += w * by_face[k].spread;
      }
    }
    std::sort(met.begin(), met.end());  // the columns in order, as the matrix keeps them
    for (std::size_t j : met) {
      out.push_back({ids_[i], ids_[j], row[j]});
      row[j] = 0;
      seen[j] = 0;
    }
    met.clear();
  }
  return out;
}

}  // namespace cosim::fluid::ibm
