// The error model of `cosim run --target`: tolerances as written, the scale a tolerance asks
// for on manufactured sequences, and no scale from levels that do not converge.
#include <gtest/gtest.h>

#include <cmath>

#include "coupler/study/argument_error.hpp"
#include "coupler/study/convergence.hpp"
#include "coupler/target/error_model.hpp"
#include "coupler/target/target.hpp"

namespace cosim::target {
namespace {

TEST(Tolerance, PercentIsRelativeAndANumberAbsolute) {
  const Tolerance relative = parse_tolerance("0.5%");
  EXPECT_TRUE(relative.relative);
  EXPECT_DOUBLE_EQ(relative.value, 0.005);
  EXPECT_DOUBLE_EQ(relative.absolute(-2.0), 0.01);
  EXPECT_TRUE(parse_tolerance("1 %").relative);
  const Tolerance absolute = parse_tolerance("1e-4");
  EXPECT_FALSE(absolute.relative);
  EXPECT_DOUBLE_EQ(absolute.absolute(-2.0), 1e-4);
  for (const char* bad : {"", "%", "abc", "0", "-1%", "1e-4x", "nan"})
    EXPECT_THROW(parse_tolerance(bad), std::invalid_argument) << bad;
}

TEST(Budget, SecondsMinutesHours) {
  EXPECT_DOUBLE_EQ(parse_budget("600"), 600);
  EXPECT_DOUBLE_EQ(parse_budget("90s"), 90);
  EXPECT_DOUBLE_EQ(parse_budget("10m"), 600);
  EXPECT_DOUBLE_EQ(parse_budget("2h"), 7200);
  for (const char* bad : {"", "m", "10d", "-5", "0"}) EXPECT_THROW(parse_budget(bad), study::ArgumentError) << bad;
}

// phi(s) = phi0 + C s^-p on three levels at scales 1/r^2, 1/r and 1 (r = 1.5): the model
// gives back p and phi0, and the scale it names has C s^-p x 1.25 at the tolerance.
TEST(Predict, ManufacturedSequencesGiveTheScaleThatMeetsTheTolerance) {
  const double r = 1.5;
  for (const double p : {1.0, 2.0, 3.0})
    for (const double c : {0.3, -0.3}) {
      const double phi0 = 2.0;
      const auto phi = [&](double s) { return phi0 + c * std::pow(s, -p); };
      const study::Estimate e = study::estimate(phi(1), phi(1 / r), phi(1 / (r * r)), r, r);
      const Fit fit = predict(e, phi(1), 1, parse_tolerance("0.1%"));
      ASSERT_TRUE(fit.prediction) << fit.why_none;
      const Prediction& pr = *fit.prediction;
      EXPECT_NEAR(pr.order, p, 1e-9);
      EXPECT_NEAR(pr.extrapolate, phi0, 1e-12);
      EXPECT_NEAR(pr.tolerance, 0.002, 1e-12);
      EXPECT_NEAR(kSafety * std::abs(phi(pr.scale) - phi0), pr.tolerance, 1e-12) << p;
      EXPECT_NEAR(modelled_error(pr, 1, pr.scale), pr.tolerance, 1e-12);
      EXPECT_GT(pr.scale, 1);  // 0.3 off at the scene: finer than it
    }
}

TEST(Predict, NoScaleFromLevelsThatDoNotConvergeMonotonically) {
  const Tolerance t = parse_tolerance("1%");
  const Fit oscillating = predict(study::estimate(1.0, 1.1, 0.85, 1.5, 1.5), 1.0, 1, t);
  EXPECT_FALSE(oscillating.prediction);
  EXPECT_EQ(oscillating.why_none,
            "the three levels oscillate about their limit, so there is no error model to "
            "extrapolate from");
  EXPECT_FALSE(predict(study::estimate(1.4, 1.2, 1.1, 1.5, 1.5), 1.4, 1, t).prediction);  // moving apart
}

}  // namespace
}  // namespace cosim::target
