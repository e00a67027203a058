// Quantities of interest: the expressions, their errors, and their values on a run file
// written as the coupler writes one.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>

#include "coupler/field/field_frame.hpp"
#include "coupler/output/run_file.hpp"
#include "coupler/scene/error.hpp"
#include "coupler/study/argument_error.hpp"
#include "coupler/study/measure.hpp"
#include "coupler/study/measures.hpp"

namespace cosim::study {
namespace {

std::string parse_error(const std::string& text) {
  try {
    parse_measure("q", text);
  } catch (const ArgumentError& e) {
    return e.what();
  }
  return "";
}

TEST(Measure, ErrorsPointAtTheRestOfTheText) {
  EXPECT_EQ(parse_error("max(body:ball:velocity.q)"), "at 'q)': expected the component x, y or z");
  EXPECT_EQ(parse_error("max(body:ball:speed.x)"),
            "at 'speed.x)': expected position, velocity, angular_velocity, force or torque");
  EXPECT_EQ(parse_error("peak(body:ball:velocity.x)"),
            "at 'peak(body:ball:velocity.x)': unknown function 'peak'; expected max, min, final, mean or abs");
  EXPECT_EQ(parse_error("body:ball:velocity.x"),
            "at 'body:ball:velocity.x': a series is one number per window: take max(...), min(...), final(...) or "
            "mean(..., t0, t1) of it");
  EXPECT_EQ(parse_error("max(body:ball:velocity.x"), "at the end: expected ')'");
  EXPECT_EQ(parse_error("max(body:ball:velocity.x) + 1"), "at '+ 1': expected the end of the measure");
  EXPECT_EQ(parse_error("max(final(body:ball:velocity.x))"),
            "at 'final(body:ball:velocity.x))': max() takes a series (body:NAME:DATASET.COMPONENT, "
            "field:PARTICIPANT:FIELD), not a number");
  EXPECT_EQ(parse_error("mean(body:ball:velocity.x, 1, 0.5)"), "at '0.5)': mean() needs t1 > t0 (t0 = 1)");
  EXPECT_EQ(parse_error("mean(body:ball:velocity.x, 1)"), "at ')': expected ','");
  EXPECT_EQ(parse_error("max(body::velocity.x)"), "at ':velocity.x)': expected a body's name after 'body:'");
  EXPECT_EQ(parse_error(" abs( min( body:ball-2:force.y ) ) "), "");
  EXPECT_EQ(parse_error("final(field::velocity.x)"), "at ':velocity.x)': expected a participant's name after 'field:'");
  EXPECT_EQ(parse_error("final(field:fluid:.x)"),
            "at '.x)': expected a field's name (velocity, pressure, density, ...)");
  EXPECT_EQ(parse_error("final(field:fluid:velocity.w)"), "at 'w)': expected the component x, y or z");
  EXPECT_EQ(parse_error("final(field:fluid:pressure)"), "");
}

TEST(Measure, NamesItsBodiesAndItsLatestTime) {
  const Measure m = parse_measure("q", "abs(mean(body:ball-2:force.y, 0.5, 1.5))");
  EXPECT_EQ(bodies_of(m.expression), std::vector<std::string>{"ball-2"});
  EXPECT_EQ(latest_time(m.expression), 1.5);
  EXPECT_EQ(latest_time(parse_measure("q", "final(body:b:position.x)").expression), 0.0);
  const Measure f = parse_measure("q", "max(abs(field:fluid:velocity.z))");
  EXPECT_EQ(participants_of(f.expression), std::vector<std::string>{"fluid"});
  EXPECT_TRUE(bodies_of(f.expression).empty());
}

// A run of 11 rows, t = 0, 0.1, ..., 1: the ball's velocity.x is t - 0.5, its position.z 2 t.
// Participant p writes fields at t = 0, 0.5 and 1 on two cells of widths 1 and 2 along x:
// the scalar s is 10 t in both, the vector u has x 1 and 4 (volume-weighted mean 3, plain
// mean 2.5) and y 10 t in the second (mean 20 t / 3).
class OnARunFile : public ::testing::Test {
 protected:
  void SetUp() override {
    file_ = std::filesystem::temp_directory_path() / ("cosim-study-measure-" + std::to_string(getpid()) + ".h5");
    auto run = output::RunFile::create(file_, output::RunInfo::of_this_build("", "scene.yaml"), {"ball"}, {"p"});
    for (int k = 0; k <= 10; ++k) {
      const double t = 0.1 * k;
      output::WindowRecord w;
      w.window = static_cast<std::uint64_t>(k);
      w.time = t;
      w.poses = {0, 0, 2 * t, 1, 0, 0, 0, t - 0.5, 0, 0, 0, 0, 0};
      w.forces = {0, -3, 0, 0, 0, 0};
      run.append(w);
      if (k % 5 == 0) {
        const field::RectilinearGrid grid{{std::vector<double>{0, 1, 3}, {0, 1}, {0, 1}}};
        run.write_fields("p", w.window, t, {grid, {{"s", 1, {10 * t, 10 * t}}, {"u", 3, {1, 0, 0, 4, 10 * t, 0}}}});
      }
    }
  }
  void TearDown() override { std::filesystem::remove(file_); }
  double value(const std::string& text) const { return evaluate(parse_measure("q", text).expression, file_); }

  std::filesystem::path file_;
};

TEST_F(OnARunFile, ExtremesFinalAndAbsoluteValues) {
  EXPECT_DOUBLE_EQ(value("max(body:ball:velocity.x)"), 0.5);
  EXPECT_DOUBLE_EQ(value("min(body:ball:velocity.x)"), -0.5);
  EXPECT_DOUBLE_EQ(value("final(body:ball:position.z)"), 2.0);
  EXPECT_DOUBLE_EQ(value("abs(min(body:ball:velocity.x))"), 0.5);
  EXPECT_NEAR(value("min(abs(body:ball:velocity.x))"), 0.0, 1e-15);
  EXPECT_DOUBLE_EQ(value("final(body:ball:force.y)"), -3.0);
}

// The trapezoidal rule is exact on a linear series, also between rows.
TEST_F(OnARunFile, MeanIsTheTimeAverageOverTheInterval) {
  EXPECT_NEAR(value("mean(body:ball:position.z, 0.05, 0.95)"), 1.0, 1e-12);
  EXPECT_NEAR(value("mean(body:ball:velocity.x, 0, 1)"), 0.0, 1e-12);
  EXPECT_NEAR(value("mean(body:ball:velocity.x, 0.6, 0.8)"), 0.2, 1e-12);
  EXPECT_THROW(value("mean(body:ball:velocity.x, 0.5, 1.5)"), std::runtime_error);
  // The last row's time, summed from windows, may fall short of time.end by round-off.
  EXPECT_NEAR(value("mean(body:ball:velocity.x, 0, 1.0000000000001)"), 0.0, 1e-12);
}

TEST_F(OnARunFile, FieldsAreVolumeWeightedMeansOverTheGrid) {
  EXPECT_NEAR(value("final(field:p:s)"), 10.0, 1e-12);
  EXPECT_NEAR(value("max(field:p:u.x)"), 3.0, 1e-12);
  EXPECT_NEAR(value("final(field:p:u.y)"), 20.0 / 3, 1e-12);
  EXPECT_NEAR(value("mean(field:p:u.y, 0, 1)"), 10.0 / 3, 1e-12);  // linear between the frames
  for (const char* bad : {"final(field:p:u)", "final(field:p:s.y)", "final(field:p:w)", "final(field:q:s)"})
    EXPECT_THROW(value(bad), std::runtime_error) << bad;
}

// A point takes the value of the cell holding it; a box weighs each cell by its overlap.
TEST_F(OnARunFile, FieldsAtAPointOrOverABox) {
  EXPECT_NEAR(value("final(field:p:u.x@[0.5, 0.5, 0.5])"), 1.0, 1e-12);
  EXPECT_NEAR(value("final(field:p:u.x@[2, 0.5, 0.5])"), 4.0, 1e-12);
  EXPECT_NEAR(value("final(field:p:u.x@[3, 1, 1])"), 4.0, 1e-12);  // the grid's last nodes are in its last cell
  EXPECT_NEAR(value("final(field:p:u.x@[0.5, 0, 0]..[2, 1, 1])"), (0.5 * 1 + 1 * 4) / 1.5, 1e-12);
  EXPECT_NEAR(value("mean(field:p:u.y@[1.5, 0.2, 0.2], 0, 1)"), 5.0, 1e-12);
  EXPECT_THROW(value("final(field:p:u.x@[5, 0, 0]..[6, 1, 1])"), std::runtime_error);
  EXPECT_THROW(value("final(field:p:u.x@[-1, 0.5, 0.5])"), std::runtime_error);
}

TEST(ParseMeasure, RegionsAreThreeCoordinatesEach) {
  EXPECT_EQ(parse_error("final(field:fluid:velocity.x@[1, 2])"), "at '])': expected ','");
  EXPECT_EQ(parse_error("final(field:fluid:velocity.x@[1, 2, z])"), "at 'z])': expected a coordinate in metres");
  EXPECT_EQ(parse_error("final(field:fluid:velocity.x@[0, 0, 0]..[1, 0, 1])"),
            "at '[1, 0, 1])': a box's upper corner must exceed its lower one on every axis");
  EXPECT_EQ(parse_error("final(field:fluid:pressure@[0, 0, 0]..[1, 1, 1])"), "");
}

const char* kScene = R"(time: {end: 1}
coupling: {window: 0.1}
domain: {min: [0, 0, 0], max: [1, 1, 1]}
bodies: [{name: ball, shape: {type: sphere, radius: 0.1}, material: {density: 1}, position: [0.5, 0.5, 0.5]}]
study:
  measure:
    top: max(body:ball:position.z)
)";

std::string argument_error(const std::string& text, const std::string& argument) {
  try {
    measures_of(scene::load_scene_from_string(text, "scene.yaml"), {argument});
  } catch (const ArgumentError& e) {
    return e.what();
  } catch (const scene::SceneError& e) {
    return std::string("scene: ") + e.what();
  }
  return "";
}

TEST(Measures, SceneAndCommandLineTogether) {
  const auto scene = scene::load_scene_from_string(kScene, "scene.yaml");
  auto both = measures_of(scene, {"low=min(body:ball:position.z)"});
  ASSERT_EQ(both.size(), 2u);
  EXPECT_EQ(both[0].name, "top");
  EXPECT_EQ(both[1].name, "low");
  // A --measure of a scene's name replaces it.
  const auto replaced = measures_of(scene, {"top=final(body:ball:position.z)"});
  ASSERT_EQ(replaced.size(), 1u);
  EXPECT_EQ(replaced[0].text, "final(body:ball:position.z)");
}

TEST(Measures, ErrorsNameTheArgumentOrTheSceneKey) {
  EXPECT_EQ(argument_error(kScene, "peak"),
            "--measure peak: expected NAME=EXPRESSION, such as peak=max(body:ball:velocity.z)");
  EXPECT_EQ(argument_error(kScene, "v=max(body:bal:velocity.x)"),
            "--measure v=max(body:bal:velocity.x): no body 'bal' in the scene (its bodies: ball)");
  EXPECT_EQ(argument_error(kScene, "v=max(body:ball:velocity.w)"),
            "--measure v=max(body:ball:velocity.w): at 'w)': expected the component x, y or z");
  EXPECT_EQ(argument_error(kScene, "v=mean(body:ball:velocity.x, 0, 5)"),
            "--measure v=mean(body:ball:velocity.x, 0, 5): mean() reaches t = 5 s, past time.end = 1 s");
  EXPECT_EQ(argument_error(kScene, "a b=max(body:ball:velocity.x)"),
            "--measure a b=max(body:ball:velocity.x): the name: expected a name of 1 to 31 letters, digits, '_' and "
            "'-'");
  EXPECT_EQ(argument_error(std::string(kScene) + "    bad: max(body:ball:position.q)\n", "v=max(body:ball:velocity.x)"),
            "scene: scene.yaml:8: study.measure.bad = max(body:ball:position.q): at 'q)': expected the component x, y "
            "or z");
  EXPECT_EQ(argument_error(kScene, "u=final(field:fluid:velocity.x)"),
            "--measure u=final(field:fluid:velocity.x): no participant 'fluid' in the scene (its participants: none)");
}

TEST(Measures, AFieldsRegionMustMeetTheDomain) {
  const std::string scene = R"(time: {end: 1}
coupling: {window: 0.1}
output: {fields_every: 1}
domain: {min: [0, 0, 0], max: [1, 1, 1]}
participants: {fluid: {dt: 0.1, options: {density: 1, viscosity: {model: newtonian, mu: 1}, grid: {cells: [4, 4, 4]}}}}
)";
  EXPECT_EQ(argument_error(scene, "u=final(field:fluid:velocity.x@[0.5, 0.5, 0.5])"), "");
  EXPECT_EQ(argument_error(scene, "u=final(field:fluid:velocity.x@[0.5, 2, 0.5])"),
            "--measure u=final(field:fluid:velocity.x@[0.5, 2, 0.5]): the field's region [2, 2] on axis y lies outside "
            "the domain [0, 1]");
}

}  // namespace
}  // namespace cosim::study
