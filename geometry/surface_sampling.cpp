#include "geometry/surface_sampling.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>

#include "geometry/queries.hpp"

namespace cosim::geometry {
namespace {

constexpr int kRefinement = 6;  // lattice cells per spacing

// The lattice's axes: all three, or the two of a section's plane.
struct Lattice {
  std::vector<int> axes;
  int fixed_axis = -1;
  double fixed_at = 0;
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  double width = 0;  // of the coarse cells: the spacing

  int dims() const { return static_cast<int>(axes.size()); }
  Eigen::Vector3d point(const std::array<double, 3>& coordinates) const {
    Eigen::Vector3d x = origin;
    for (int d = 0; d < dims(); ++d) x[axes[d]] += coordinates[d];
    if (fixed_axis >= 0) x[fixed_axis] = fixed_at;
    return x;
  }
};

struct Candidate {
  Eigen::Vector3d point, normal;
  double weight;
};

// The root of the signed distance on the segment a-b, whose ends have opposite signs
// (Illinois false position: bracketed, superlinear).
Eigen::Vector3d crossing(const Shape& shape, const Pose& pose, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                         double fa, double fb) {
  double ta = 0, tb = 1;
  const double tolerance = 1e-12;
  for (int i = 0; i < 60 && tb - ta > tolerance; ++i) {
    const double t = (ta * fb - tb * fa) / (fb - fa);
    const double f = signed_distance(shape, pose, a + t * (b - a));
    if ((f <= 0) == (fa <= 0)) {
      ta = t;
      fa = f;
      fb /= 2;  // Illinois: keep the stale end from stalling the bracket
    } else {
      tb = t;
      fb = f;
      fa /= 2;
    }
    if (f == 0) return a + t * (b - a);
  }
  return a + 0.5 * (ta + tb) * (b - a);
}

// The signed distance's gradient at x by central differences `step` wide: the outward
// normal on the surface, where a closest-point query from a point a rounding error off it
// divides that error by itself (an ellipsoid's normal there is noise).
Eigen::Vector3d gradient(const Shape& shape, const Pose& pose, const Eigen::Vector3d& x, double step) {
  Eigen::Vector3d g;
  for (int d = 0; d < 3; ++d) {
    const Eigen::Vector3d e = step * Eigen::Vector3d::Unit(d);
    g[d] = signed_distance(shape, pose, x + e) - signed_distance(shape, pose, x - e);
  }
  return g;
}

// Candidates on the lattice edges of one coarse cell that the surface crosses. The cell owns
// its edges half-open (not those on its upper faces), so neighbours count each edge once.
void cell_candidates(const Shape& shape, const Pose& pose, const Lattice& lattice, const std::array<int, 3>& cell,
                     std::vector<Candidate>& out) {
  const int dims = lattice.dims(), n = kRefinement;
  const double c = lattice.width / n;
  std::array<int, 3> count{1, 1, 1};
  for (int d = 0; d < dims; ++d) count[d] = n + 1;
  const auto index = [&](const std::array<int, 3>& v) { return v[0] + count[0] * (v[1] + count[1] * v[2]); };
  std::vector<Eigen::Vector3d> nodes(static_cast<std::size_t>(count[0] * count[1] * count[2]));
  for (int k = 0; k < count[2]; ++k)
    for (int j = 0; j < count[1]; ++j)
      for (int i = 0; i < count[0]; ++i) {
        const std::array<int, 3> v{i, j, k};
        std::array<double, 3> x{};
        for (int d = 0; d < dims; ++d) x[d] = (cell[d] * n + v[d]) * c;
        nodes[static_cast<std::size_t>(index(v))] = lattice.point(x);
      }
  std::vector<double> phi(nodes.size());
  signed_distances(shape, pose, nodes, phi);
  for (int along = 0; along < dims; ++along)
    for (int k = 0; k < std::min(count[2], n); ++k)
      for (int j = 0; j < std::min(count[1], n); ++j)
        for (int i = 0; i < std::min(count[0], n); ++i) {
          const std::array<int, 3> v{i, j, k};
          std::array<int, 3> w = v;
          ++w[along];
          const auto a = static_cast<std::size_t>(index(v)), b = static_cast<std::size_t>(index(w));
          if ((phi[a] <= 0) == (phi[b] <= 0)) continue;
          const Eigen::Vector3d x = crossing(shape, pose, nodes[a], nodes[b], phi[a], phi[b]);
          Eigen::Vector3d normal = gradient(shape, pose, x, c / 2);
          if (lattice.fixed_axis >= 0) normal[lattice.fixed_axis] = 0;
          const double norm = normal.norm();
          if (!(norm > 1e-12)) continue;  // a face lying in the section's plane
          normal /= norm;
          double l1 = 0;
          for (int d = 0; d < dims; ++d) l1 += std::abs(normal[lattice.axes[d]]);
          out.push_back({x, normal, std::pow(c, dims - 1) / l1});
        }
}

std::vector<Candidate> candidates(const Shape& shape, const Pose& pose, const Lattice& lattice,
                                  const std::array<int, 3>& cells) {
  const int dims = lattice.dims();
  std::array<int, 3> nodes_count{1, 1, 1};
  for (int d = 0; d < dims; ++d) nodes_count[d] = cells[d] + 1;
  std::vector<Eigen::Vector3d> nodes;
  for (int k = 0; k < nodes_count[2]; ++k)
    for (int j = 0; j < nodes_count[1]; ++j)
      for (int i = 0; i < nodes_count[0]; ++i) {
        std::array<double, 3> x{};
        const std::array<int, 3> v{i, j, k};
        for (int d = 0; d < dims; ++d) x[d] = v[d] * lattice.width;
        nodes.push_back(lattice.point(x));
      }
  std::vector<double> phi(nodes.size());
  signed_distances(shape, pose, nodes, phi);
  // A cell the surface meets has a corner within half its diagonal of the surface.
  const double near = 0.5 * std::sqrt(static_cast<double>(dims)) * lattice.width * (1 + 1e-9);
  std::vector<Candidate> out;
  std::array<int, 3> corner_count{1, 1, 1};
  for (int d = 0; d < dims; ++d) corner_count[d] = 2;
  for (int k = 0; k < std::max(1, cells[2]); ++k)
    for (int j = 0; j < std::max(1, cells[1]); ++j)
      for (int i = 0; i < cells[0]; ++i) {
        double closest = std::numeric_limits<double>::infinity();
        for (int ck = 0; ck < corner_count[2]; ++ck)
          for (int cj = 0; cj < corner_count[1]; ++cj)
            for (int ci = 0; ci < corner_count[0]; ++ci) {
              const std::size_t at =
                  static_cast<std::size_t>(i + ci + nodes_count[0] * (j + cj + nodes_count[1] * (k + ck)));
              closest = std::min(closest, std::abs(phi[at]));
            }
        if (closest <= near) cell_candidates(shape, pose, lattice, {i, j, k}, out);
      }
  return out;
}

// Points of a set (candidates, by their index) by the cell of width `width` they fall in, on
// a dense grid of such cells from the lattice's origin over the candidates' box (at most
// twice as many cells as the lattice has coarse nodes there), each a list threaded through `next_`.
class PointGrid {
 public:
  PointGrid(const Lattice& lattice, double width, const std::vector<Candidate>& candidates)
      : lattice_(lattice), width_(width) {
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
    Eigen::Vector3d hi = -lo;
    for (const Candidate& c : candidates) {
      lo = lo.cwiseMin(c.point);
      hi = hi.cwiseMax(c.point);
    }
    std::size_t cells = 1;
    for (std::size_t d = 0; d < static_cast<std::size_t>(lattice.dims()) && !candidates.empty(); ++d) {
      first_[d] = unclamped(lo, d);
      count_[d] = unclamped(hi, d) - first_[d] + 1;
      cells *= static_cast<std::size_t>(count_[d]);
    }
    head_.assign(candidates.empty() ? 0 : cells, -1);
    next_.assign(candidates.size(), -1);
  }

  // `id` indexes the candidates the grid was made for; x is that candidate's point.
  void insert(const Eigen::Vector3d& x, int id) {
    auto& h = head_[index(cell_of(x))];
    next_[static_cast<std::size_t>(id)] = h;
    h = id;
  }
  // Calls f(id) for the points in the cells within `rings` of x's.
  template <typename F>
  void near(const Eigen::Vector3d& x, int rings, F&& f) const {
    const Cell c = cell_of(x);
    Cell lo{0, 0, 0}, hi{0, 0, 0};
    for (std::size_t d = 0; d < static_cast<std::size_t>(lattice_.dims()); ++d) {
      lo[d] = std::max<std::int64_t>(c[d] - rings, 0);
      hi[d] = std::min<std::int64_t>(c[d] + rings, count_[d] - 1);
    }
    for (std::int64_t k = lo[2]; k <= hi[2]; ++k)
      for (std::int64_t j = lo[1]; j <= hi[1]; ++j)
        for (std::int64_t i = lo[0]; i <= hi[0]; ++i)
          for (int id = head_[index({i, j, k})]; id >= 0; id = next_[static_cast<std::size_t>(id)]) f(id);
  }
  // The cell x lies in, as one number.
  std::size_t cell_number(const Eigen::Vector3d& x) const { return index(cell_of(x)); }

 private:
  using Cell = std::array<std::int64_t, 3>;
  // The lattice's cells of this width, numbered from its origin.
  std::int64_t unclamped(const Eigen::Vector3d& x, std::size_t d) const {
    const int axis = lattice_.axes[d];
    return static_cast<std::int64_t>(std::floor((x[axis] - lattice_.origin[axis]) / width_));
  }
  Cell cell_of(const Eigen::Vector3d& x) const {
    Cell c{0, 0, 0};
    for (std::size_t d = 0; d < static_cast<std::size_t>(lattice_.dims()); ++d)
      c[d] = std::clamp<std::int64_t>(unclamped(x, d) - first_[d], 0, count_[d] - 1);
    return c;
  }
  std::size_t index(const Cell& c) const {
    return static_cast<std::size_t>(c[0] + count_[0] * (c[1] + count_[1] * c[2]));
  }

  const Lattice& lattice_;
  double width_;
  Cell first_{0, 0, 0}, count_{1, 1, 1};  // the grid's cells of the lattice's, per axis
  std::vector<int> head_;                 // per cell: its last point, or -1
  std::vector<int> next_;                 // per point: the one before it in its cell, or -1
};

double squared_distance(const Lattice& lattice, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  double s = 0;
  for (int axis : lattice.axes) s += (a[axis] - b[axis]) * (a[axis] - b[axis]);
  return s;
}

// Random sequential adsorption: candidates in a seeded random order, each kept unless a
// kept one lies within `gap`.
std::vector<int> adsorb(const std::vector<Candidate>& candidates, const Lattice& lattice, double gap) {
  std::vector<int> order(candidates.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::mt19937_64 random(20261126);
  for (std::size_t i = order.size(); i > 1; --i)  // Fisher-Yates: the same on every library
    std::swap(order[i - 1], order[static_cast<std::size_t>(random() % i)]);
  PointGrid kept(lattice, gap, candidates);
  std::vector<int> out;
  for (int c : order) {
    bool free = true;
    kept.near(candidates[static_cast<std::size_t>(c)].point, 1, [&](int k) {
      free = free && squared_distance(lattice, candidates[static_cast<std::size_t>(c)].point,
                                      candidates[static_cast<std::size_t>(k)].point) >= gap * gap;
    });
    if (!free) continue;
    kept.insert(candidates[static_cast<std::size_t>(c)].point, c);
    out.push_back(c);
  }
  return out;
}

// For each candidate, the index (into `points`) of the nearest point, of equals the first:
// the cells within one ring of width 2 spacing hold every point closer than that, and the
// points lie about one spacing apart; farther rings only for a candidate with none so close.
// The candidates are taken cell by cell (`order_`, made once for all the iterations), so the
// points around a cell are gathered once for every candidate in it.
class NearestPoint {
 public:
  NearestPoint(const std::vector<Candidate>& candidates, const Lattice& lattice, double spacing)
      : candidates_(candidates), lattice_(lattice), width_(2 * spacing) {
    const PointGrid grid(lattice, width_, candidates);
    std::vector<std::pair<std::size_t, int>> by_cell;
    for (std::size_t c = 0; c < candidates.size(); ++c)
      by_cell.emplace_back(grid.cell_number(candidates[c].point), static_cast<int>(c));
    std::sort(by_cell.begin(), by_cell.end());
    for (std::size_t i = 0; i < by_cell.size(); ++i) {
      if (i == 0 || by_cell[i].first != by_cell[i - 1].first) first_.push_back(i);
      order_.push_back(by_cell[i].second);
    }
    first_.push_back(order_.size());
  }

  std::vector<int> owners(const std::vector<int>& points) const {
    std::vector<int> out(candidates_.size(), -1);
    if (points.empty()) return out;
    PointGrid grid(lattice_, width_, candidates_);
    for (int p : points) grid.insert(candidates_[static_cast<std::size_t>(p)].point, p);
    std::vector<int> rank(candidates_.size(), -1);  // a point's index into `points`
    for (std::size_t p = 0; p < points.size(); ++p) rank[static_cast<std::size_t>(points[p])] = static_cast<int>(p);
    std::vector<int> around;
    for (std::size_t g = 0; g + 1 < first_.size(); ++g) {
      around.clear();
      grid.near(candidates_[static_cast<std::size_t>(order_[first_[g]])].point, 1,
                [&](int p) { around.push_back(rank[static_cast<std::size_t>(p)]); });
      for (std::size_t i = first_[g]; i < first_[g + 1]; ++i) {
        const auto c = static_cast<std::size_t>(order_[i]);
        double best = std::numeric_limits<double>::infinity();
        const auto consider = [&](int p) {
          const double d =
              squared_distance(lattice_, candidates_[c].point, candidates_[static_cast<std::size_t>(points[p])].point);
          if (d < best || (d == best && p < out[c])) {
            best = d;
            out[c] = p;
          }
        };
        for (int p : around) consider(p);
        for (int rings = 2; out[c] < 0; ++rings)
          grid.near(candidates_[c].point, rings, [&](int p) { consider(rank[static_cast<std::size_t>(p)]); });
      }
    }
    return out;
  }

 private:
  const std::vector<Candidate>& candidates_;
  const Lattice& lattice_;
  double width_;
  std::vector<int> order_;          // the candidates, cell by cell
  std::vector<std::size_t> first_;  // cell g's candidates: order_[first_[g]] .. order_[first_[g + 1]]
};

// The lattice's candidates around the shape, with `lattice.width` set to the spacing.
std::vector<Candidate> all_candidates(const Shape& shape, const Pose& pose, double spacing, Lattice& lattice) {
  if (!(spacing > 0)) throw std::invalid_argument("surface sampling: the spacing must be > 0");
  // A container's surface is its inside's, facing inwards.
  if (const auto* container = std::get_if<Container>(&shape)) {
    std::vector<Candidate> out = all_candidates(free_inside(*container), pose, spacing, lattice);
    for (Candidate& c : out) c.normal = -c.normal;
    return out;
  }
  if (!is_bounded(shape)) throw std::invalid_argument("surface sampling: a half-space has no bounded surface");
  const Aabb box = world_aabb(shape, pose);
  lattice.width = spacing;
  // Shifted by irrational fractions of a lattice cell, so that no lattice plane lies in a
  // face of an axis-aligned shape or touches a round one (either would count its crossings
  // twice).
  lattice.origin = box.min - spacing * Eigen::Vector3d(1.0 + 0.3819660 / kRefinement, 1.0 + 0.2360680 / kRefinement,
                                                       1.0 + 0.1458980 / kRefinement);
  std::array<int, 3> cells{0, 0, 0};
  for (int d = 0; d < lattice.dims(); ++d) {
    const int axis = lattice.axes[static_cast<std::size_t>(d)];
    cells[d] = static_cast<int>(std::ceil((box.max[axis] - box.min[axis]) / spacing)) + 2;
  }
  return candidates(shape, pose, lattice, cells);
}

std::vector<SurfaceSample> sample(const Shape& shape, const Pose& pose, double spacing, Lattice lattice) {
  const std::vector<Candidate> all = all_candidates(shape, pose, spacing, lattice);
  if (all.empty()) return {};
  const double gap = (lattice.dims() == 3 ? 0.8 : 0.748) * spacing;
  std::vector<int> points = adsorb(all, lattice, gap);
  const NearestPoint nearest(all, lattice, spacing);
  std::vector<int> owner;
  for (int iteration = 0; iteration < 30; ++iteration) {
    owner = nearest.owners(points);
    std::vector<Eigen::Vector3d> centroid(points.size(), Eigen::Vector3d::Zero());
    std::vector<double> weight(points.size(), 0.0);
    for (std::size_t c = 0; c < all.size(); ++c) {
      centroid[static_cast<std::size_t>(owner[c])] += all[c].weight * all[c].point;
      weight[static_cast<std::size_t>(owner[c])] += all[c].weight;
    }
    // Each point moves to the candidate it owns that lies closest to its centroid.
    std::vector<int> moved = points;
    std::vector<double> best(points.size(), std::numeric_limits<double>::infinity());
    for (std::size_t c = 0; c < all.size(); ++c) {
      const auto p = static_cast<std::size_t>(owner[c]);
      const double d = squared_distance(lattice, all[c].point, centroid[p] / weight[p]);
      if (d < best[p]) {
        best[p] = d;
        moved[p] = static_cast<int>(c);
      }
    }
    if (moved == points) break;
    points = std::move(moved);
  }
  owner = nearest.owners(points);
  std::vector<SurfaceSample> out(points.size());
  for (std::size_t p = 0; p < points.size(); ++p)
    out[p] = {all[static_cast<std::size_t>(points[p])].point, all[static_cast<std::size_t>(points[p])].normal, 0.0};
  for (std::size_t c = 0; c < all.size(); ++c) out[static_cast<std::size_t>(owner[c])].area += all[c].weight;
  return out;
}

}  // namespace

std::vector<SurfaceSample> sample_surface(const Shape& shape, const Pose& pose, double spacing) {
  return sample(shape, pose, spacing, {.axes = {0, 1, 2}});
}

namespace {
Lattice section_lattice(int axis, double at) {
  if (axis < 0 || axis > 2) throw std::invalid_argument("surface sampling: a section's axis must be 0, 1 or 2");
  Lattice lattice{.axes = {}, .fixed_axis = axis, .fixed_at = at};
  for (int d = 0; d < 3; ++d)
    if (d != axis) lattice.axes.push_back(d);
  return lattice;
}
}  // namespace

std::vector<SurfaceSample> section_boundary(const Shape& shape, const Pose& pose, int axis, double at, double spacing) {
  Lattice lattice = section_lattice(axis, at);
  std::vector<SurfaceSample> out;
  for (const Candidate& c : all_candidates(shape, pose, spacing, lattice)) out.push_back({c.point, c.normal, c.weight});
  return out;
}

std::vector<SurfaceSample> sample_section(const Shape& shape, const Pose& pose, int axis, double at, double spacing) {
  return sample(shape, pose, spacing, section_lattice(axis, at));
}

}  // namespace cosim::geometry
