// `cosim run --target` end to end on the partitioned oscillator, whose exact answer says
// whether the level it chose really meets the tolerance.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <regex>

#include "tests/integration/cosim_process.hpp"
#include "tests/integration/oscillator_scene.hpp"

namespace cosim::testing {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

constexpr const char* kMeasure = "x1=final(body:m1:position.x)";

// A scene of the oscillator with x1(1 s) as its measure, at 50 windows of 20 ms.
std::string scene_in(const std::filesystem::path& dir, const OscillatorScene& s) {
  write_file(dir / "oscillator.yaml", s.yaml());
  return (dir / "oscillator.yaml").string();
}

OscillatorScene coarse() {
  OscillatorScene s;
  s.end = 1.0;
  s.window = 0.02;
  s.dt_mass = s.dt_spring = 0.002;
  return s;
}

double number_after(const std::string& text, const std::string& before) {
  std::smatch m;
  const std::regex re(before + " (-?[0-9.e+-]+)");
  if (!std::regex_search(text, m, re)) return NAN;
  return std::stod(m[1]);
}

// Serial-implicit coupling with Verlet is second order in the window; the scene as written
// is about 1e-4 off in x1(1 s), so 1e-5 asks for a level about three times as fine.
TEST(Target, ChosenLevelMeetsTheToleranceAgainstTheExactAnswer) {
  const OscillatorScene s = coarse();
  const auto dir = scratch_dir("target_oscillator");
  const auto out = dir / "target";
  const auto r =
      run_cosim({"run", scene_in(dir, s), "--target", "x1=1e-5", "--measure", kMeasure, "--out", out.string()});
  std::cout << r.output;
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("level 4 ("));
  EXPECT_THAT(r.output, HasSubstr("cosim run --target: estimate: "));
  EXPECT_THAT(r.output, HasSubstr("the target 1e-5 is met"));
  const double value = number_after(r.output, "x1 =");
  const double exact = s.physics.at(s.end)[0];
  std::cout << "level 4: x1 = " << value << ", exact " << exact << ", error " << std::abs(value - exact) << "\n";
  EXPECT_LT(std::abs(value - exact), 1e-5);
  // A level 4 as coarse as the scene would be 1e-4 off: the one chosen is finer by about
  // sqrt(1.25e-4 / 1e-5) = 3.5.
  const double scale = number_after(r.output, "\\),");
  EXPECT_GT(scale, 2.5);
  EXPECT_LT(scale, 5);
  for (const char* f : {"level_4.yaml", "level_4.h5", "report.md", "results.csv"})
    EXPECT_TRUE(std::filesystem::exists(out / f)) << f;
  EXPECT_THAT(read_file(out / "report.md"), HasSubstr("## Target: x1 within 1e-5"));
}

// A tolerance the scene's own run already meets costs no fourth level; a level over the
// budget is refused before it runs; a tolerance that is no number runs nothing.
TEST(Target, MetAlreadyRefusedOverBudgetOrBadArgument) {
  const OscillatorScene s = coarse();
  const auto dir = scratch_dir("target_refusals");
  const std::string scene = scene_in(dir, s);
  const auto met = run_cosim({"run", scene, "--target", "x1=1%", "--measure", kMeasure, "--out", (dir / "a").string()});
  EXPECT_EQ(met.exit_code, 0) << met.output;
  EXPECT_THAT(met.output, HasSubstr("already meets the target"));
  EXPECT_FALSE(std::filesystem::exists(dir / "a" / "level_4.yaml"));

  const auto over = run_cosim(
      {"run", scene, "--target", "x1=1e-7", "--measure", kMeasure, "--budget", "1s", "--out", (dir / "b").string()});
  EXPECT_EQ(over.exit_code, 1) << over.output;
  EXPECT_THAT(over.output, HasSubstr("level 4 refused: it is estimated at"));
  EXPECT_THAT(over.output, HasSubstr("over --budget 1.0 s"));
  EXPECT_FALSE(std::filesystem::exists(dir / "b" / "level_4.h5"));

  const auto bad =
      run_cosim({"run", scene, "--target", "x1=one", "--measure", kMeasure, "--out", (dir / "c").string()});
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_THAT(bad.output, HasSubstr("--target x1=one: tolerance 'one': expected a positive number"));
  const auto unknown =
      run_cosim({"run", scene, "--target", "x2=1%", "--measure", kMeasure, "--out", (dir / "c").string()});
  EXPECT_EQ(unknown.exit_code, 2) << unknown.output;
  EXPECT_THAT(unknown.output, HasSubstr("no measure x2 (the measures are x1)"));
  EXPECT_FALSE(std::filesystem::exists(dir / "c" / "level_1.h5"));
}

}  // namespace
}  // namespace cosim::testing
