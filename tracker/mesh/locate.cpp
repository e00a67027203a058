#include "tracker/mesh/locate.hpp"

#include "tracker/mesh/geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cosim::tracker::mesh {

PointLocator::PointLocator(const Mesh& mesh) : mesh_(&mesh) {
  const Index cells = mesh.cell_count();
  std::vector<Vec3> cell_lo(cells), cell_hi(cells);
  lo_ = Vec3::Constant(std::numeric_limits<double>::infinity());
  hi_ = -lo_;
  for (Index c = 0; c < cells; ++c) {
    const Eigen::AlignedBox3d box = cell_box(mesh, c);
    double off_plane = 0.0;
    for (Index f = mesh.cell_faces[c]; f < mesh.cell_faces[c + 1]; ++f)
      for (Index k = 0; k < mesh.vertex_count(f); ++k)
        off_plane =
            std::max(off_plane, std::abs(mesh.faces[f].normal.dot(mesh.face_vertex(f, k) - mesh.faces[f].point)));
    // The cell is its planes' intersection, which pokes out of the vertices' box by the
    // order of the faces' non-planarity.
    const double pad = 4.0 * off_plane + 1e-9 * box.diagonal().norm();
    cell_lo[c] = box.min().array() - pad;
    cell_hi[c] = box.max().array() + pad;
    lo_ = lo_.cwiseMin(cell_lo[c]);
    hi_ = hi_.cwiseMax(cell_hi[c]);
  }
  const Vec3 size = (hi_ - lo_).cwiseMax(Vec3::Constant(1e-300));
  const double width = std::cbrt(size.prod() / std::max<Index>(cells, 1));
  for (int k = 0; k < 3; ++k) {
    buckets_[k] = std::clamp(static_cast<int>(std::lround(size[k] / width)), 1, 1024);
    inverse_width_[k] = buckets_[k] / size[k];
  }

  // Two passes over the same ranges: count, then fill.
  const std::size_t total = std::size_t(buckets_[0]) * buckets_[1] * buckets_[2];
  bucket_begin_.assign(total + 1, 0);
  const auto for_each_bucket = [&](Index c, auto&& visit) {
    const auto a = bucket_of(cell_lo[c]), b = bucket_of(cell_hi[c]);
    for (int k = a[2]; k <= b[2]; ++k)
      for (int j = a[1]; j <= b[1]; ++j)
        for (int i = a[0]; i <= b[0]; ++i) visit(i + buckets_[0] * (j + std::size_t(buckets_[1]) * k));
  };
  for (Index c = 0; c < cells; ++c) for_each_bucket(c, [&](std::size_t b) { ++bucket_begin_[b + 1]; });
  for (std::size_t b = 0; b < total; ++b) bucket_begin_[b + 1] += bucket_begin_[b];
  bucket_cells_.resize(bucket_begin_[total]);
  std::vector<Index> next(bucket_begin_.begin(), bucket_begin_.end() - 1);
  for (Index c = 0; c < cells; ++c) for_each_bucket(c, [&](std::size_t b) { bucket_cells_[next[b]++] = c; });
}

std::array<int, 3> PointLocator::bucket_of(const Vec3& x) const {
  std::array<int, 3> b{};
  for (int k = 0; k < 3; ++k)
    b[k] = std::clamp(static_cast<int>((x[k] - lo_[k]) * inverse_width_[k]), 0, buckets_[k] - 1);
  return b;
}

Index PointLocator::locate(const Vec3& x) const {
  if ((x.array() < lo_.array()).any() || (x.array() > hi_.array()).any()) return -1;
  const auto b = bucket_of(x);
  const std::size_t bucket = b[0] + buckets_[0] * (b[1] + std::size_t(buckets_[1]) * b[2]);
  for (Index i = bucket_begin_[bucket]; i < bucket_begin_[bucket + 1]; ++i)
    if (contains(*mesh_, bucket_cells_[i], x)) return bucket_cells_[i];
  return -1;
}

}  // namespace cosim::tracker::mesh
