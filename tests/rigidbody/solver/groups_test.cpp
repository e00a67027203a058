// Contact groups connect through dynamic bodies only.
#include <gtest/gtest.h>

#include "rigidbody/solver/contact_groups.hpp"

namespace cosim::rigidbody::solver {
namespace {

contact::PairContacts between(std::uint32_t a, std::uint32_t b) { return {.a = a, .b = b, .count = 1}; }

std::vector<dynamics::BodyInertia> ground_and(int dynamic) {
  std::vector<dynamics::BodyInertia> inertias{dynamics::BodyInertia::fixed()};
  for (int i = 0; i < dynamic; ++i) inertias.push_back(dynamics::BodyInertia::of(1.0, Eigen::Matrix3d::Identity()));
  return inertias;
}

TEST(ContactGroups, TwoPilesOnOneGroundAreSeparate) {
  const auto inertias = ground_and(4);
  // Piles {1, 2} and {3, 4}, both standing on the ground 0.
  const std::vector<contact::PairContacts> manifolds{between(0, 1), between(0, 3), between(1, 2), between(4, 3)};
  const auto groups = contact_groups(inertias, manifolds);
  ASSERT_EQ(groups.size(), 2u);
  EXPECT_EQ(groups[0], (std::vector<std::uint32_t>{0, 2}));
  EXPECT_EQ(groups[1], (std::vector<std::uint32_t>{1, 3}));
}

TEST(ContactGroups, ChainIsOneGroup) {
  const auto inertias = ground_and(4);
  const std::vector<contact::PairContacts> manifolds{between(0, 1), between(1, 2), between(3, 2), between(3, 4),
                                                     between(4, 0)};
  const auto groups = contact_groups(inertias, manifolds);
  ASSERT_EQ(groups.size(), 1u);
  EXPECT_EQ(groups[0].size(), 5u);
}

TEST(ContactGroups, FixedPairsBelongNowhere) {
  auto inertias = ground_and(1);
  inertias.push_back(dynamics::BodyInertia::fixed());
  const std::vector<contact::PairContacts> manifolds{between(0, 2), between(1, 2)};
  const auto groups = contact_groups(inertias, manifolds);
  ASSERT_EQ(groups.size(), 1u);
  EXPECT_EQ(groups[0], (std::vector<std::uint32_t>{1}));
}

}  // namespace
}  // namespace cosim::rigidbody::solver
