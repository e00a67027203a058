// Bricks of a structured box by recursive coordinate bisection: every cell in the brick of
// its owner, the bricks tiling the box, loads even to within a slab, the cuts restored.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <stdexcept>
#include <vector>

#include "tracker/parallel/bricks.hpp"

namespace cosim::tracker::parallel {
namespace {

std::array<int, 3> hex_of(Index cell, const std::array<int, 3>& n, int per_hex) {
  return mesh::box_cell(cell, n, per_hex).hex;
}

// Each cell's owner's brick holds it; the bricks' hexahedra add up to the box's.
void expect_tiling(const Bricks& bricks, const std::array<int, 3>& n, int per_hex) {
  const Index cells = n[0] * n[1] * n[2] * per_hex;
  long long in_bricks = 0;
  for (int p = 0; p < bricks.parts(); ++p) in_bricks += bricks.brick(p).hexahedra();
  EXPECT_EQ(in_bricks, 1LL * n[0] * n[1] * n[2]);
  for (Index c = 0; c < cells; ++c) {
    const int owner = bricks.owner(c);
    ASSERT_GE(owner, 0);
    ASSERT_LT(owner, bricks.parts());
    const Bricks::Range& r = bricks.brick(owner);
    const std::array<int, 3> at = hex_of(c, n, per_hex);
    for (int a = 0; a < 3; ++a) ASSERT_TRUE(at[a] >= r.lo[a] && at[a] < r.hi[a]) << "cell " << c;
  }
}

TEST(Bricks, TileTheBoxWithEvenCounts) {
  const std::array<int, 3> n{10, 7, 5};
  for (const int per_hex : {1, 6})
    for (const int parts : {1, 2, 3, 4, 5, 8}) {
      const Bricks bricks(n, per_hex, parts, {});
      ASSERT_EQ(bricks.parts(), parts);
      expect_tiling(bricks, n, per_hex);
      long long most = 0;
      for (int p = 0; p < parts; ++p) most = std::max(most, bricks.brick(p).hexahedra());
      // Each cut misses its share by at most half a slab (at most 35 hexahedra here).
      EXPECT_LE(most, 350 / parts + 35) << parts << " parts";
    }
}

TEST(Bricks, WeightsSplitWhereTheParticlesAre) {
  // All the weight in x < 3 of 12: four parts cut there, not across the empty rest.
  const std::array<int, 3> n{12, 4, 4};
  std::vector<double> weight(12 * 4 * 4, 0.0);
  for (Index c = 0; c < 12 * 4 * 4; ++c)
    if (hex_of(c, n, 1)[0] < 3) weight[static_cast<std::size_t>(c)] = 10.0;
  const Bricks bricks(n, 1, 4, weight);
  expect_tiling(bricks, n, 1);
  std::vector<double> load(4, 0.0);
  for (Index c = 0; c < 12 * 4 * 4; ++c)
    load[static_cast<std::size_t>(bricks.owner(c))] += weight[static_cast<std::size_t>(c)];
  const double mean = 480.0 / 4;
  for (const double l : load) EXPECT_LE(l, 1.34 * mean);  // slabs of 40 or 80 against 120 each
  // Cells alone would have cut at x = 6 first and left three parts with nothing.
  EXPECT_GT(*std::min_element(load.begin(), load.end()), 0.0);
}

TEST(Bricks, CutsRestoreTheSameBricks) {
  const std::array<int, 3> n{9, 8, 3};
  std::vector<double> weight(9 * 8 * 3 * 6);
  for (std::size_t c = 0; c < weight.size(); ++c) weight[c] = static_cast<double>(c % 17);
  const Bricks bricks(n, 6, 5, weight);
  const Bricks again = Bricks::from_cuts(n, 6, 5, bricks.cuts());
  EXPECT_TRUE(again == bricks);
  for (Index c = 0; c < 9 * 8 * 3 * 6; ++c) ASSERT_EQ(again.owner(c), bricks.owner(c));
  std::vector<int> cuts = bricks.cuts();
  cuts.pop_back();
  EXPECT_THROW(Bricks::from_cuts(n, 6, 5, cuts), std::invalid_argument);
  cuts = bricks.cuts();
  cuts.push_back(1);
  EXPECT_THROW(Bricks::from_cuts(n, 6, 5, cuts), std::invalid_argument);
  cuts = bricks.cuts();
  cuts[0] = 0;
  EXPECT_THROW(Bricks::from_cuts(n, 6, 5, cuts), std::invalid_argument);
}

TEST(Bricks, MorePartsThanHexahedraLeaveSomeEmpty) {
  const std::array<int, 3> n{2, 1, 1};
  const Bricks bricks(n, 6, 4, {});
  expect_tiling(bricks, n, 6);
  int empty = 0;
  for (int p = 0; p < 4; ++p) empty += bricks.brick(p).hexahedra() == 0;
  EXPECT_EQ(empty, 2);
  EXPECT_THROW(Bricks(n, 1, 0, {}), std::invalid_argument);
  EXPECT_THROW(Bricks({0, 1, 1}, 1, 2, {}), std::invalid_argument);
  EXPECT_THROW(Bricks(n, 1, 2, std::vector<double>(3, 1.0)), std::invalid_argument);
}

}  // namespace
}  // namespace cosim::tracker::parallel
