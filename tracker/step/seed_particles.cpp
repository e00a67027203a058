#include "tracker/step/seed_particles.hpp"

#include <algorithm>
#include <array>
#include <memory>
#include <cmath>
#include <random>
#include <stdexcept>
#include <utility>

#include "tracker/dsmc/random.hpp"
#include "tracker/mesh/geometry.hpp"

namespace cosim::tracker::step {
namespace {

// Bounding-box draws before giving up on a sliver of a cell (then its centroid is taken):
// even a Kuhn tetrahedron fills 1/6 of its box.
constexpr int kTries = 1000;

enum class Drawn : std::uint64_t { range_share = 0, cell_particles = 1 };

// pcg64 keeps 127 bits of a stream number (the top bit is lost to the increment's low one):
// bit 126 set, so that no stream of the run's other generators (collisions: below 2^64)
// is one of these; the round (of total, or the region's index in regions) from bit 65, what
// is drawn at bit 64, the key (a cell, or a range a << 32 | b of 31-bit cell indices) below.
dsmc::Rng keyed(std::uint64_t seed, std::uint64_t round, Drawn what, std::uint64_t key) {
  using Stream = pcg_extras::pcg128_t;
  return dsmc::Rng(
      seed, Stream(1) << 126 | Stream(round) << 65 | Stream(static_cast<std::uint64_t>(what)) << 64 | Stream(key));
}

class Seeder {
 public:
  Seeder(const mesh::Mesh& mesh, const tracking::Obstacles& obstacles, const Seeding& seeding,
         const parallel::Decomposition& cells)
      : mesh_(mesh),
        obstacles_(obstacles),
        seeding_(seeding),
        states_(static_cast<std::size_t>(obstacles.count())),
        gas_{seeding.drift, sigma(seeding.temperature)},
        swarm_(obstacles.count()) {
    // A part's own cells come first, in the whole's order.
    for (Index c = 0; c < mesh.own_cells(); ++c)
      if (const Index g = mesh.global_cell(c); cells.owns(g)) owned_.push_back({g, c});
  }

  tracking::Swarm per_cell() {
    for (const auto& [global, local] : owned_) {
      dsmc::Rng rng = stream(global, 0);
      draw(rng, local, seeding_.per_cell, gas_);
    }
    return std::move(swarm_);
  }

  // What per_cell() keeps, without keeping it: whole cells where the walls keep all draws or
  // none, elsewhere the cell draws as per_cell() does, velocities too, since they come from
  // the same stream as the positions.
  std::size_t per_cell_count() {
    std::size_t kept = 0;
    for (const auto& [global, local] : owned_) {
      if (const Walls walls = walls_in(local); walls != Walls::cut) {
        kept += walls == Walls::none ? static_cast<std::size_t>(seeding_.per_cell) : 0;
      } else {
        dsmc::Rng rng = stream(global, 0);
        kept += static_cast<std::size_t>(draw(rng, local, seeding_.per_cell, gas_, nullptr, false));
      }
    }
    return kept;
  }

  tracking::Swarm total(const parallel::Ranks& ranks, const CellVolumes& volumes) {
    volumes_ = &volumes;
    long long wanted = seeding_.total, drawn = 0;
    for (std::uint64_t round = 0; wanted > 0; ++round) {
      drawn += wanted;
      wanted -= ranks.sum(split(0, volumes.cells, wanted, round));
      if (wanted > 0 && drawn > kTries * (static_cast<long long>(seeding_.total) + 1))
        throw std::runtime_error("particles: the walls leave (almost) no free space to seed in");
    }
    return std::move(swarm_);
  }

  tracking::Swarm regions(const CellVolumes& volumes) {
    each_region(volumes, true);
    return std::move(swarm_);
  }
  std::size_t regions_count(const CellVolumes& volumes) {
    return static_cast<std::size_t>(each_region(volumes, false));
  }

 private:
  // The drift and the thermal spread per component (sqrt(k_B T / m)) of the velocities drawn.
  struct Gas {
    Vec3 drift;
    double sigma;
  };
  double sigma(double temperature) const { return std::sqrt(boltzmann * temperature / seeding_.mass); }

  // Where no object has primitives, the states, and so whether a draw falls inside a wall,
  // are the same everywhere in the cell: a cell's draws are all free or all inside a wall,
  // as its centroid is.
  enum class Walls { none, whole, cut };
  Walls walls_in(Index cell) {
    if (obstacles_.empty()) return Walls::none;
    if (!obstacles_.active(obstacles_.bounding_cell(cell)).empty()) return Walls::cut;
    obstacles_.classify(cell, mesh_.centroid[cell], states_);
    return obstacles_.inside_wall(cell, states_) ? Walls::whole : Walls::none;
  }

  dsmc::Rng stream(Index global, std::uint64_t round) const {
    return keyed(seeding_.seed, round, Drawn::cell_particles, static_cast<std::uint64_t>(global));
  }

  // Cell by cell, each region's draws in the cell; returns how many are kept. Counting only
  // (`add` false), a cell wholly inside the region that the walls keep all draws of or none
  // needs no draws beyond its count's.
  long long each_region(const CellVolumes& volumes, bool add) {
    std::vector<RegionShape> shapes;
    std::vector<Gas> gases;
    for (const SeedRegion& r : seeding_.regions) {
      shapes.emplace_back(r.shape);
      gases.push_back({r.velocity, sigma(r.temperature)});
    }
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    long long kept = 0;
    for (const auto& [global, local] : owned_) {
      const Eigen::AlignedBox3d box = mesh::cell_box(mesh_, local);
      // The whole's volumes, not the part's: every rank count draws the same counts.
      const double volume = volumes.below(global + 1) - volumes.below(global);
      for (std::size_t i = 0; i < shapes.size(); ++i) {
        const RegionShape::Cover cover = shapes[i].cover(box, mesh_.centroid[local]);
        if (cover == RegionShape::Cover::outside) continue;
        dsmc::Rng rng = stream(global, i);
        const double expected = seeding_.regions[i].number_density * volume / seeding_.weight;
        auto n = static_cast<long long>(expected);
        if (unit(rng) < expected - static_cast<double>(n)) ++n;
        if (!add && cover == RegionShape::Cover::inside) {
          if (const Walls walls = walls_in(local); walls != Walls::cut) {
            kept += walls == Walls::none ? n : 0;
            continue;
          }
        }
        kept += draw(rng, local, n, gases[i], cover == RegionShape::Cover::cut ? &shapes[i] : nullptr, add);
      }
    }
    return kept;
  }

  // Splits n draws over the cells [a, b) by volume and draws this rank's; returns how many
  // of those are free.
  long long split(Index a, Index b, long long n, std::uint64_t round) {
    const auto first = std::lower_bound(owned_.begin(), owned_.end(), std::pair<Index, Index>{a, -1});
    if (n == 0 || first == owned_.end() || first->first >= b) return 0;
    if (b - a == 1) {
      dsmc::Rng rng = stream(a, round);
      return draw(rng, first->second, n, gas_);
    }
    const Index m = a + (b - a) / 2;
    const double below = volumes_->below(a);
    const double share = std::clamp((volumes_->below(m) - below) / (volumes_->below(b) - below), 0.0, 1.0);
    dsmc::Rng rng = keyed(seeding_.seed, round, Drawn::range_share,
                          static_cast<std::uint64_t>(a) << 32 | static_cast<std::uint64_t>(b));
    const long long low = std::binomial_distribution<long long>(n, share)(rng);
    return split(a, m, low, round) + split(m, b, n - low, round);
  }

  // n uniform draws in the cell, from the cell's stream `rng`; adds those inside `region`
  // (none: all) and outside every wall, with `gas`'s Maxwellian velocities, unless `add` is
  // false; returns how many.
  long long draw(dsmc::Rng& rng, Index cell, long long n, const Gas& gas, const RegionShape* region = nullptr,
                 bool add = true) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    // normal_distribution needs a positive deviation: a cold gas draws no thermal part.
    std::normal_distribution<double> gauss(0.0, gas.sigma > 0 ? gas.sigma : 1.0);
    const Eigen::AlignedBox3d box = mesh::cell_box(mesh_, cell);
    long long kept = 0;
    for (long long i = 0; i < n; ++i) {
      Vec3 x = mesh_.centroid[cell];
      for (int t = 0; t < kTries; ++t) {
        Vec3 y;
        for (int a = 0; a < 3; ++a) y[a] = box.min()[a] + unit(rng) * (box.max()[a] - box.min()[a]);
        if (mesh::contains(mesh_, cell, y)) {
          x = y;
          break;
        }
      }
      if (region != nullptr && !region->contains(x)) continue;
      obstacles_.classify(cell, x, states_);
      if (obstacles_.inside_wall(cell, states_)) continue;
      const Vec3 thermal = gas.sigma > 0 ? Vec3(gauss(rng), gauss(rng), gauss(rng)) : Vec3::Zero();
      if (add) swarm_.add({x, gas.drift + thermal, cell}, states_);
      ++kept;
    }
    return kept;
  }

  const mesh::Mesh& mesh_;
  const tracking::Obstacles& obstacles_;
  const Seeding& seeding_;
  std::vector<std::pair<Index, Index>> owned_;  // (in the whole, here), ascending
  const CellVolumes* volumes_ = nullptr;
  std::vector<csg::State> states_;
  Gas gas_;  // per_cell's and total's
  tracking::Swarm swarm_;
};

}  // namespace

CellVolumes volumes_of(const mesh::Mesh& whole) {
  // Monotone prefix sums: a range's share of a larger one is in [0, 1] despite round-off.
  auto prefix = std::make_shared<std::vector<double>>(1, 0.0);
  for (const double v : whole.volume) prefix->push_back(prefix->back() + v);
  return {whole.cell_count(), [prefix](Index c) { return (*prefix)[static_cast<std::size_t>(c)]; }};
}

CellVolumes volumes_of(const mesh::BoxSpec& box) {
  std::array<std::vector<double>, 3> nodes;
  for (int a = 0; a < 3; ++a) nodes[a] = mesh::axis_nodes(box.axes[a]);
  const Index nx = static_cast<Index>(nodes[0].size()) - 1, ny = static_cast<Index>(nodes[1].size()) - 1,
              nz = static_cast<Index>(nodes[2].size()) - 1, per_hex = box.tetrahedra ? 6 : 1;
  const auto from_first = [nodes](int a, Index i) { return nodes[a][static_cast<std::size_t>(i)] - nodes[a][0]; };
  const auto width = [nodes](int a, Index i) {
    return nodes[a][static_cast<std::size_t>(i) + 1] - nodes[a][static_cast<std::size_t>(i)];
  };
  const double wx = from_first(0, nx), wy = from_first(1, ny), wz = from_first(2, nz);
  const Index cells = nx * ny * nz * per_hex;
  // Whole layers in z, then whole rows in y of the layer, then whole hexahedra of the row,
  // then tetrahedra of the hexahedron.
  return {cells, [=](Index c) {
            if (c >= cells) return wx * wy * wz;
            const mesh::BoxCell at = mesh::box_cell(c, {nx, ny, nz}, per_hex);
            const Index i = at.hex[0], j = at.hex[1], k = at.hex[2];
            return from_first(2, k) * wy * wx +
                   width(2, k) *
                       (from_first(1, j) * wx +
                        width(1, j) * (from_first(0, i) + width(0, i) * static_cast<double>(at.within) / per_hex));
          }};
}

tracking::Swarm seed_particles(const mesh::Mesh& mesh, const tracking::Obstacles& obstacles, const Seeding& seeding,
                               const parallel::Decomposition& cells, const CellVolumes& volumes) {
  Seeder seeder(mesh, obstacles, seeding, cells);
  if (!seeding.regions.empty()) return seeder.regions(volumes);
  return seeding.per_cell > 0 ? seeder.per_cell() : seeder.total(cells.ranks(), volumes);
}

std::size_t seeded_count(const mesh::Mesh& whole, const tracking::Obstacles& obstacles, const Seeding& seeding) {
  const parallel::Decomposition one(whole, parallel::Ranks());
  if (!seeding.regions.empty()) return Seeder(whole, obstacles, seeding, one).regions_count(volumes_of(whole));
  if (seeding.per_cell == 0) return static_cast<std::size_t>(seeding.total);  // rounds until exactly that many
  return Seeder(whole, obstacles, seeding, one).per_cell_count();
}

}  // namespace cosim::tracker::step
