// make_accelerator maps every scene setting to the accelerator of the same name, with w.
#include <stdexcept>

#include <gtest/gtest.h>

#include "tests/coupling/problems.hpp"

namespace cosim::coupling::test {
namespace {

// Iterates are compared bit for bit: the same algorithm with the same w gives the same
// numbers, and any other choice differs within three updates on this problem.
Window three_updates(Accelerator& accelerator) {
  const Problem problem = linear(Eigen::VectorXd::LinSpaced(4, -2.0, 0.5), 31);
  return iterate(accelerator, problem, Eigen::VectorXd::Zero(4), 3);
}

void expect_same(const Window& a, const Window& b) {
  ASSERT_EQ(a.iterates.size(), b.iterates.size());
  for (std::size_t k = 0; k < a.iterates.size(); ++k) {
    EXPECT_TRUE((a.iterates[k].array() == b.iterates[k].array()).all()) << "iterate " << k;
  }
}

TEST(MakeAccelerator, MapsEveryKind) {
  const double w = 0.3;
  expect_same(three_updates(*make_accelerator(Acceleration::None, w)), three_updates(*make_fixed_point()));
  expect_same(three_updates(*make_accelerator(Acceleration::Constant, w)), three_updates(*make_constant(w)));
  expect_same(three_updates(*make_accelerator(Acceleration::Aitken, w)), three_updates(*make_aitken(w)));
  expect_same(three_updates(*make_accelerator(Acceleration::IqnIls, w)), three_updates(*make_iqn_ils(w)));
}

TEST(MakeAccelerator, KindsAreDistinguishable) {
  const double w = 0.3;
  const Window windows[] = {three_updates(*make_fixed_point()), three_updates(*make_constant(w)),
                            three_updates(*make_aitken(w)), three_updates(*make_iqn_ils(w))};
  for (std::size_t i = 0; i < 4; ++i) {
    for (std::size_t j = i + 1; j < 4; ++j) {
      EXPECT_FALSE(windows[i].x().isApprox(windows[j].x(), 1e-12)) << i << " vs " << j;
    }
  }
}

TEST(MakeAccelerator, RejectsAValueOutsideTheEnum) {
  EXPECT_THROW(make_accelerator(static_cast<Acceleration>(99), 0.5), std::invalid_argument);
}

}  // namespace
}  // namespace cosim::coupling::test
