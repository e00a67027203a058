// A rank's part of a mesh (owned cells and two layers of ghosts) and moves handed over
// between parts: particles tracked through the parts of three "ranks" in one process end
// where the whole mesh puts them, bit for bit, with the same logical states.

#include "tracker/csg/shapes.hpp"
#include "tracker/mesh/box_mesh.hpp"
#include "tracker/mesh/box_part.hpp"
#include "tracker/mesh/geometry.hpp"
#include "tracker/mesh/part.hpp"
#include "tracker/tracking/handover.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <functional>
#include <memory>
#include <tuple>
#include <vector>

namespace cosim::tracker::tracking {
namespace {

constexpr int kRanks = 3;

// Owners that interleave (slabs in x and y), so moves cross between parts often.
std::vector<int> interleaved_owners(const mesh::Mesh& mesh) {
  std::vector<int> owner;
  for (const Vec3& c : mesh.centroid)
    owner.push_back((static_cast<int>(4 * c.x()) + static_cast<int>(3 * c.y())) % kRanks);
  return owner;
}

std::function<int(Index)> table(const std::vector<int>& owner) {
  return [&owner](Index c) { return owner[static_cast<std::size_t>(c)]; };
}

bool same_face(const mesh::Face& a, const mesh::Face& b) {
  return a.normal == b.normal && a.point == b.point && a.shift == b.shift;
}

TEST(Part, HasItsCellsAndTwoLayersOfNeighboursWithTheWholesFaces) {
  for (const mesh::BoxSpec& spec : {mesh::cube(5), mesh::cube(4, true)}) {
    mesh::BoxSpec periodic = spec;
    periodic.periodic = {true, false, false};
    for (const mesh::BoxSpec& s : {spec, periodic}) {
      const mesh::Mesh whole = mesh::box_mesh(s);
      const std::vector<int> owner = interleaved_owners(whole);
      for (int rank = 0; rank < kRanks; ++rank) {
        const mesh::Mesh part = mesh::extract_part(whole, table(owner), rank);
        const mesh::PartCells cells(part);
        const auto owned = static_cast<Index>(std::count(owner.begin(), owner.end(), rank));
        ASSERT_EQ(part.own_cells(), owned);
        EXPECT_EQ(part.whole_diagonal, mesh::whole_diagonal(whole));
        std::vector<int> layer(static_cast<std::size_t>(part.cell_count()), 2);
        for (Index c = 0; c < part.cell_count(); ++c) {
          const Index g = part.global_cell(c);
          EXPECT_EQ(cells.local(g), c);
          EXPECT_EQ(owner[g] == rank, c < owned) << "owned cells first";
          EXPECT_EQ(part.volume[c], whole.volume[g]);
          EXPECT_EQ(part.centroid[c], whole.centroid[g]);
          ASSERT_EQ(part.cell_faces[c + 1] - part.cell_faces[c], whole.cell_faces[g + 1] - whole.cell_faces[g]);
          for (Index k = 0; k < part.cell_faces[c + 1] - part.cell_faces[c]; ++k) {
            const Index f = part.cell_faces[c] + k, wf = whole.cell_faces[g] + k;
            const mesh::Face &a = part.faces[f], &b = whole.faces[wf];
            EXPECT_TRUE(same_face(a, b));
            ASSERT_EQ(part.vertex_count(f), whole.vertex_count(wf));
            for (Index v = 0; v < part.vertex_count(f); ++v)
              EXPECT_EQ(part.face_vertex(f, v), whole.face_vertex(wf, v));
            if (b.neighbour < 0) {
              EXPECT_EQ(a.neighbour, b.neighbour);
            } else if (a.neighbour == mesh::kBeyondPart) {
              EXPECT_EQ(cells.local(b.neighbour), -1);
            } else {
              EXPECT_EQ(part.global_cell(a.neighbour), b.neighbour);
              EXPECT_EQ(part.faces[a.twin].twin, f);
              EXPECT_EQ(part.cell_of_face(a.twin), a.neighbour);
            }
          }
        }
        // Layers: 0 owned; a cell next to layer k is in layer k + 1 at most.
        for (Index c = 0; c < owned; ++c) layer[c] = 0;
        for (int k = 0; k < 2; ++k)
          for (Index c = 0; c < part.cell_count(); ++c)
            if (layer[c] == k)
              for (Index f = part.cell_faces[c]; f < part.cell_faces[c + 1]; ++f) {
                const Index n = part.faces[f].neighbour;
                ASSERT_NE(n, mesh::kBeyondPart) << "a neighbour of layer " << k << " missing";
                if (n >= 0) layer[n] = std::min(layer[n], k + 1);
              }
        // Layer by layer, each in the whole's order.
        for (Index c = 1; c < part.cell_count(); ++c) {
          EXPECT_LE(layer[c - 1], layer[c]);
          if (layer[c - 1] == layer[c]) {
            EXPECT_LT(part.global_cell(c - 1), part.global_cell(c));
          }
        }
        EXPECT_LT(cells.local(-5), 0);
      }
    }
  }
}

// A box's part built from a box around the brick is the part of the whole box, to the bit:
// graded axes, tetrahedra, periodic axes that wrap and that do not.
TEST(Part, OfABoxIsBuiltWithoutTheWhole) {
  mesh::BoxSpec spec = mesh::cube(7, true);
  spec.axes[0] = {.min = -1.0, .max = 2.0, .cells = 11, .ratio = 3.0};
  spec.axes[2].cells = 9;
  for (const std::array<bool, 3> periodic : {std::array{false, false, false}, std::array{true, false, true}}) {
    spec.periodic = periodic;
    const mesh::Mesh whole = mesh::box_mesh(spec);
    // Bricks: a corner, the middle, a slab through the box.
    const std::array<std::array<std::array<int, 3>, 2>, 3> bricks{
        {{{{0, 0, 0}, {4, 3, 2}}}, {{{3, 2, 3}, {8, 5, 6}}}, {{{5, 0, 0}, {6, 7, 9}}}}};
    for (const auto& [lo, hi] : bricks) {
      const auto owner = [&](Index c) {
        const std::array<int, 3> at = mesh::box_cell(c, {11, 7, 9}, 6).hex;
        for (int a = 0; a < 3; ++a)
          if (at[a] < lo[a] || at[a] >= hi[a]) return 1;
        return 0;
      };
      const mesh::Mesh a = mesh::box_part(spec, lo, hi, owner, 0), b = mesh::extract_part(whole, owner, 0);
      ASSERT_EQ(a.global, b.global);
      EXPECT_EQ(a.ghosts, b.ghosts);
      EXPECT_EQ(a.whole_diagonal, b.whole_diagonal);
      EXPECT_EQ(a.cell_faces, b.cell_faces);
      EXPECT_EQ(a.vertices, b.vertices);
      EXPECT_EQ(a.face_vertex_index, b.face_vertex_index);
      EXPECT_EQ(a.volume, b.volume);
      EXPECT_EQ(a.centroid, b.centroid);
      EXPECT_EQ(a.patches, b.patches);
      ASSERT_EQ(a.faces.size(), b.faces.size());
      for (std::size_t f = 0; f < a.faces.size(); ++f) {
        EXPECT_EQ(a.faces[f].normal, b.faces[f].normal);
        EXPECT_EQ(a.faces[f].point, b.faces[f].point);
        EXPECT_EQ(a.faces[f].neighbour, b.faces[f].neighbour) << "face " << f;
        EXPECT_EQ(a.faces[f].twin, b.faces[f].twin);
        EXPECT_EQ(a.shifts[a.faces[f].shift], b.shifts[b.faces[f].shift]);
      }
    }
  }
  EXPECT_THROW(mesh::box_part(
                   spec, {0, 0, 0}, {0, 1, 1}, [](Index) { return 0; }, 0),
               std::invalid_argument);
}

// One "rank": its part, walls and obstacles registered on it, its particles.
struct Rank {
  std::unique_ptr<mesh::Mesh> mesh;
  std::unique_ptr<Domain> domain;
  std::unique_ptr<Obstacles> obstacles;
  std::unique_ptr<mesh::PartCells> cells;
  Swarm swarm;
  Handover away;
  std::vector<ObstacleTally> tallies;
  explicit Rank(int objects) : swarm(objects), away(objects), tallies(static_cast<std::size_t>(objects)) {}
};

using Key = std::tuple<Index, double, double, double, double, double, double, std::vector<csg::State>>;
Key key(const Particle& p, Index global, std::span<const csg::State> states) {
  return {global, p.x.x(), p.x.y(), p.x.z(), p.v.x(), p.v.y(), p.v.z(), {states.begin(), states.end()}};
}

TEST(Handover, MovesThroughThreePartsEndWhereTheWholeMeshPutsThem) {
  const mesh::Mesh whole = mesh::box_mesh(mesh::cube(6, true));
  const Boundaries walls{std::vector<BoundaryCondition>(6), 1.0};  // specular: no random draws
  const std::vector<Obstacle> objects{{"ball", csg::Tree(csg::ball({0.5, 0.45, 0.55}, 0.2)), false, {}},
                                      {"zone", csg::Tree(csg::ball({0.3, 0.3, 0.3}, 0.15)), true, {}}};
  const Domain domain(whole, walls);
  const Obstacles obstacles(whole, objects);
  const std::vector<int> owner = interleaved_owners(whole);

  std::vector<Rank> ranks;
  for (int r = 0; r < kRanks; ++r) {
    ranks.emplace_back(2);
    Rank& rank = ranks.back();
    rank.mesh = std::make_unique<mesh::Mesh>(mesh::extract_part(whole, table(owner), r));
    rank.domain = std::make_unique<Domain>(*rank.mesh, walls);
    rank.obstacles = std::make_unique<Obstacles>(*rank.mesh, objects);
    rank.cells = std::make_unique<mesh::PartCells>(*rank.mesh);
    // A first-layer ghost is registered as its owner registers it: states mean the same.
    for (Index c = 0; c < rank.mesh->cell_count(); ++c)
      for (int o = 0; o < 2; ++o)
        if (bool first_layer = false; c < rank.mesh->own_cells() || [&] {
              for (Index f = rank.mesh->cell_faces[c]; f < rank.mesh->cell_faces[c + 1]; ++f)
                first_layer |=
                    rank.mesh->faces[f].neighbour >= 0 && rank.mesh->faces[f].neighbour < rank.mesh->own_cells();
              return first_layer;
            }()) {
          const auto a = rank.obstacles->cells(o).primitives(c);
          const auto b = obstacles.cells(o).primitives(rank.mesh->global_cell(c));
          ASSERT_TRUE(std::ranges::equal(a, b)) << "cell " << rank.mesh->global_cell(c);
        }
  }

  // Fast particles (several cells a step) outside the ball, on the whole mesh and on their owners.
  Swarm all(2);
  Random draw(7);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::normal_distribution<double> gauss;
  std::vector<csg::State> s(2);
  while (all.size() < 2000) {
    const Vec3 x(uniform(draw), uniform(draw), uniform(draw));
    const Index cell = domain.locator.locate(x);
    obstacles.classify(cell, x, s);
    if (obstacles.inside_wall(cell, s)) continue;
    const Vec3 v = Vec3(gauss(draw), gauss(draw), gauss(draw)).cast<float>().cast<double>();
    all.add({x, v, cell}, s);
    Rank& rank = ranks[static_cast<std::size_t>(owner[cell])];
    rank.swarm.add({x, v, rank.cells->local(cell)}, s);
  }

  Random unused(1);
  MoveTally whole_moves, part_moves;
  std::vector<ObstacleTally> whole_tallies(2);
  long long handed = 0;
  for (int step = 0; step < 5; ++step) {
    all.move_all(
        {.domain = domain, .obstacles = obstacles, .random = unused, .moves = whole_moves, .tallies = whole_tallies},
        0.4);
    for (Rank& rank : ranks)
      rank.swarm.move_all({.domain = *rank.domain,
                           .obstacles = *rank.obstacles,
                           .random = unused,
                           .moves = part_moves,
                           .tallies = rank.tallies,
                           .away = &rank.away},
                          0.4);
    // Hand over until every move is done: each particle to the owner of its ghost.
    for (bool moving = true; moving;) {
      std::vector<Handover> incoming(kRanks, Handover(2));
      moving = false;
      for (Rank& rank : ranks) {
        for (std::size_t i = 0; i < rank.away.size(); ++i) {
          Particle p = rank.away.particle(i);
          const Index g = rank.mesh->global_cell(p.cell);
          const auto to = static_cast<std::size_t>(owner[g]);
          p.cell = ranks[to].cells->local(g);
          ASSERT_LT(p.cell, ranks[to].mesh->own_cells());
          incoming[to].add(p, rank.away.states(i), rank.away.flight(i));
          ++handed;
          moving = true;
        }
        rank.away.clear();
      }
      for (int r = 0; r < kRanks; ++r) {
        Rank& rank = ranks[static_cast<std::size_t>(r)];
        incoming[r].resume_all({.domain = *rank.domain,
                                .obstacles = *rank.obstacles,
                                .random = unused,
                                .moves = part_moves,
                                .tallies = rank.tallies},
                               rank.swarm);
        rank.away = std::move(incoming[r]);
      }
    }
  }
  EXPECT_GT(handed, 2000) << "too few moves handed over to test them";
  EXPECT_EQ(part_moves.moves, whole_moves.moves);
  EXPECT_EQ(part_moves.faces_crossed, whole_moves.faces_crossed);
  EXPECT_EQ(part_moves.object_events, whole_moves.object_events);
  EXPECT_EQ(whole_moves.lost, 0);

  std::vector<Key> expected, found;
  for (std::size_t i = 0; i < all.size(); ++i) expected.push_back(key(all.particle(i), all.cell(i), all.states(i)));
  for (const Rank& rank : ranks)
    for (std::size_t i = 0; i < rank.swarm.size(); ++i)
      found.push_back(key(rank.swarm.particle(i), rank.mesh->global_cell(rank.swarm.cell(i)), rank.swarm.states(i)));
  std::sort(expected.begin(), expected.end());
  std::sort(found.begin(), found.end());
  EXPECT_TRUE(expected == found) << "the parts moved the particles elsewhere than the whole mesh";
  long long hits = 0, entered = 0;
  for (const Rank& rank : ranks) {
    hits += rank.tallies[0].hits;
    entered += rank.tallies[1].entered;
  }
  EXPECT_EQ(hits, whole_tallies[0].hits);
  EXPECT_EQ(entered, whole_tallies[1].entered);
  EXPECT_GT(whole_tallies[0].hits, 100);
}

TEST(Handover, APartWithoutAHandoverIsRefused) {
  const mesh::Mesh whole = mesh::box_mesh(mesh::cube(3));
  const std::vector<int> owner = interleaved_owners(whole);
  const mesh::Mesh part = mesh::extract_part(whole, table(owner), 0);
  const Domain domain(part, {std::vector<BoundaryCondition>(6), 1.0});
  Swarm swarm(0);
  MoveTally moves;
  Random random(1);
  const Obstacles none;
  EXPECT_THROW(swarm.move_all({.domain = domain, .obstacles = none, .random = random, .moves = moves}, 0.1),
               std::invalid_argument);
}

}  // namespace
}  // namespace cosim::tracker::tracking
