// new_window must leave nothing behind: a window after another is the same as a window on
// a fresh accelerator, iterate for iterate, which is what makes restarts exact.
#include <string>

#include <gtest/gtest.h>

#include "tests/coupling/problems.hpp"

namespace cosim::coupling::test {
namespace {

class NewWindow : public ::testing::TestWithParam<Acceleration> {};

TEST_P(NewWindow, SecondWindowMatchesAFreshAccelerator) {
  const Eigen::Index n = 6;
  const Problem first = linear(Eigen::VectorXd::LinSpaced(n, -3.0, -1.0), 21);
  const Problem second = tanh_problem(Eigen::VectorXd::LinSpaced(n, -1.0, 1.5), 2.0);
  const Eigen::VectorXd x0 = random_vector(n, 22);

  const auto used = make_accelerator(GetParam(), 0.2);
  // Stopped mid-window, so the history and Aitken's factor are far from their start.
  iterate(*used, first, Eigen::VectorXd::Zero(n), 4);
  const Window after = iterate(*used, second, x0, 30);
  const Window fresh = iterate(*make_accelerator(GetParam(), 0.2), second, x0, 30);

  ASSERT_EQ(after.iterates.size(), fresh.iterates.size());
  for (std::size_t k = 0; k < after.iterates.size(); ++k) {
    EXPECT_TRUE((after.iterates[k].array() == fresh.iterates[k].array()).all()) << "iterate " << k;
  }
}

// Named here rather than through scene::to_string, which lives in cosim_scene.
std::string name(const ::testing::TestParamInfo<Acceleration>& info) {
  switch (info.param) {
    case Acceleration::None:
      return "None";
    case Acceleration::Constant:
      return "Constant";
    case Acceleration::Aitken:
      return "Aitken";
    case Acceleration::IqnIls:
      return "IqnIls";
  }
  return "Unknown";
}

INSTANTIATE_TEST_SUITE_P(Kinds, NewWindow,
                         ::testing::Values(Acceleration::None, Acceleration::Constant, Acceleration::Aitken,
                                           Acceleration::IqnIls),
                         name);

}  // namespace
}  // namespace cosim::coupling::test
