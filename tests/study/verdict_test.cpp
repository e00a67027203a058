// The words a study prints for each regime.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "coupler/study/verdict.hpp"

namespace cosim::study {
namespace {

using ::testing::HasSubstr;

Estimate monotonic(double p) {
  Estimate e;
  e.convergence = Convergence::Monotonic;
  e.order = p;
  return e;
}

TEST(Verdict, OrderNearTheExpectedOneIsAsymptotic) {
  EXPECT_THAT(verdict(monotonic(2.1), 2.0, std::nullopt), HasSubstr("in the asymptotic range"));
  EXPECT_THAT(verdict(monotonic(1.2), 2.0, std::nullopt), HasSubstr("not in the asymptotic range"));
  EXPECT_THAT(verdict(monotonic(2.9), 2.0, std::nullopt), HasSubstr("far from the expected order 2"));
}

TEST(Verdict, WithoutAnExpectedOrderTheRangeIsNotJudged) {
  EXPECT_THAT(verdict(monotonic(2.0), std::nullopt, std::nullopt), HasSubstr("not judged"));
}

TEST(Verdict, AnOrderThatMovesBetweenTriplesHasNotSettled) {
  EXPECT_THAT(verdict(monotonic(2.0), 2.0, 1.2), HasSubstr("has not settled"));
  EXPECT_THAT(verdict(monotonic(2.0), 2.0, 1.9), HasSubstr("in the asymptotic range"));
}

TEST(Verdict, OscillatingDivergingAndUnchangedAreSaidPlainly) {
  Estimate e;
  e.convergence = Convergence::Oscillatory;
  e.order = 2.0;
  EXPECT_THAT(verdict(e, 2.0, std::nullopt), HasSubstr("oscillatory convergence (e32/e21 < 0)"));
  EXPECT_THAT(verdict(e, 2.0, std::nullopt), HasSubstr("not in the asymptotic range"));
  e.convergence = Convergence::Diverging;
  e.order.reset();
  EXPECT_THAT(verdict(e, 2.0, std::nullopt), HasSubstr("diverging"));
  e.convergence = Convergence::Unchanged;
  EXPECT_THAT(verdict(e, 2.0, std::nullopt), HasSubstr("no order"));
}

}  // namespace
}  // namespace cosim::study
