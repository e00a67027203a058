#include "tests/rigidbody/broadphase/expect_pairs.hpp"

#include <algorithm>
#include <iterator>
#include <unordered_map>

#include <gtest/gtest.h>

#include "rigidbody/broadphase/brute_force.hpp"

namespace cosim::rigidbody::broadphase::testing {

std::size_t expect_brute_force_pairs(std::span<const Object> objects, const HashGridConfig& config) {
  HashGrid grid(config);
  grid.update(objects);
  std::vector<Pair> pairs;
  grid.find_pairs(pairs);

  std::unordered_map<Id, bool> fixed;
  for (const Object& o : objects) fixed[o.id] = o.fixed;
  for (const auto& [a, b] : pairs) {
    EXPECT_LT(a, b);
    EXPECT_FALSE(fixed.at(a) && fixed.at(b)) << "fixed pair " << a << "-" << b;
  }
  std::sort(pairs.begin(), pairs.end());
  const auto twice = std::adjacent_find(pairs.begin(), pairs.end());
  EXPECT_EQ(twice, pairs.end()) << "pair " << twice->first << "-" << twice->second << " twice";

  const std::vector<Pair> expected = brute_force_pairs(objects, config.margin);
  std::vector<Pair> missing;
  std::vector<Pair> extra;
  std::set_difference(expected.begin(), expected.end(), pairs.begin(), pairs.end(), std::back_inserter(missing));
  std::set_difference(pairs.begin(), pairs.end(), expected.begin(), expected.end(), std::back_inserter(extra));
  EXPECT_TRUE(missing.empty()) << missing.size() << " pairs missing, first " << missing.front().first << "-"
                               << missing.front().second;
  EXPECT_TRUE(extra.empty()) << extra.size() << " pairs too many, first " << extra.front().first << "-"
                             << extra.front().second;
  return pairs.size();
}

}  // namespace cosim::rigidbody::broadphase::testing
