// The rigid-body scenes of configs/ run through the real programs, shortened: `cosim run`
// starts only cosim-rigidbody, standalone writes the same run file, and each scene shows
// the physics it is there for.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "tests/integration/cosim_process.hpp"
#include "tests/integration/h5_read.hpp"
#include "tests/integration/standalone_run.hpp"

namespace cosim::testing {
namespace {

namespace fs = std::filesystem;

const fs::path configs = COSIM_CONFIGS_DIR;

struct Runs {
  fs::path dir;
  Finished coupled{};
  Series position(const std::string& body) const {
    return read_series(dir / "scene.h5", "/bodies/" + body + "/position");
  }
  Series velocity(const std::string& body) const {
    return read_series(dir / "scene.h5", "/bodies/" + body + "/velocity");
  }
};

// Copies configs/<name>.yaml (and the meshes it may refer to) with time.end shortened, runs
// it through `cosim run` and standalone, and checks that both wrote the same rows for
// every body and that the coupler started cosim-rigidbody and nothing else.
Runs run_config(const std::string& name, const std::string& end, const std::vector<std::string>& bodies) {
  std::ifstream in(configs / (name + ".yaml"));
  std::stringstream text;
  text << in.rdbuf();
  const std::regex time_end(R"(time:\n  end: [^\n]+)");
  EXPECT_TRUE(std::regex_search(text.str(), time_end)) << name;
  const std::string shortened = std::regex_replace(text.str(), time_end, "time:\n  end: " + end);

  Runs runs{scratch_dir(name)};
  fs::copy(configs / "meshes", runs.dir / "meshes", fs::copy_options::recursive);
  runs.coupled = run_scene_text(runs.dir, shortened);
  EXPECT_EQ(runs.coupled.exit_code, 0) << runs.coupled.output;
  const std::string& out = runs.coupled.output;
  EXPECT_NE(out.find("participants: rigidbody ("), std::string::npos) << out;
  EXPECT_EQ(out.find("started "), out.rfind("started ")) << "more than one participant started:\n" << out;

  EXPECT_EQ(run_standalone("cosim-rigidbody", runs.dir / "scene.yaml", runs.dir / "alone.h5"), 0);
  EXPECT_EQ(read_string_attribute(runs.dir / "alone.h5", "/run", "status"), "finished");
  for (const auto& body : bodies)
    for (const char* series : {"/position", "/orientation", "/velocity", "/angular_velocity"}) {
      const auto coupled = read_series(runs.dir / "scene.h5", "/bodies/" + body + series);
      const auto alone = read_series(runs.dir / "alone.h5", "/bodies/" + body + series);
      EXPECT_EQ(alone.rows, coupled.rows) << body << series;
      EXPECT_EQ(alone.values, coupled.values) << body << series;
    }
  return runs;
}

// Guards against: the shipped cradle scene losing its ball-by-ball transfer through the program.
TEST(RigidScenes, NewtonsCradlePassesTheMomentumToTheLastBall) {
  const std::vector<std::string> balls{"ball1", "ball2", "ball3", "ball4", "ball5"};
  const auto runs = run_config("rigid_newtons_cradle", "0.1", balls);
  const double v0 = 1.0;
  for (std::size_t b = 0; b < balls.size(); ++b) {
    const auto v = runs.velocity(balls[b]);
    ASSERT_EQ(v.rows, 11u);  // t = 0 and 10 windows
    EXPECT_NEAR(v.at(v.rows - 1, 0), b + 1 == balls.size() ? v0 : 0.0, 1e-6 * v0) << balls[b];
  }
}

// The shipped pyramids' sphere names s<layer>_<i>_<j>, layers first .. end - 1, each one
// sphere shorter than the layer below along both axes (nx x ny at layer 0).
std::vector<std::string> pyramid_names(int first, int end, int nx, int ny) {
  std::vector<std::string> names;
  for (int layer = first; layer < end; ++layer)
    for (int i = 0; i < nx - layer; ++i)
      for (int j = 0; j < ny - layer; ++j)
        names.push_back("s" + std::to_string(layer) + "_" + std::to_string(i) + "_" + std::to_string(j));
  return names;
}

// Guards against: a sphere of the shipped pyramid sinking through the floor in the program.
TEST(RigidScenes, SpherePyramidStaysOnTheFloor) {
  const auto spheres = pyramid_names(0, 5, 8, 5);
  ASSERT_EQ(spheres.size(), 100u);
  const auto runs = run_config("rigid_sphere_pyramid", "0.2", spheres);
  constexpr double r = 0.05;
  for (const auto& s : spheres) {
    const auto p = runs.position(s);
    ASSERT_EQ(p.rows, 21u);
    for (std::size_t row = 0; row < p.rows; ++row) ASSERT_GE(p.at(row, 2), 0.99 * r) << s << " row " << row;
  }
}

// Guards against: the settled pyramid, the reference of the solvers' iteration study
// (scripts/study rigidbody), moving once its gaps have closed: each free sphere ends below
// its start by at most what closing the gaps beneath it takes and does not move sideways.
// A layer starts sqrt(2) r + g above the one below, whose spheres are 2 (r + g) apart
// (g = 1e-3 r), and rests sqrt(4 r^2 - 2 (r + g)^2) ~ sqrt(2) (r - g) above it: it drops
// (1 + sqrt(2)) g per layer.
TEST(RigidScenes, SettledPyramidStandsOnItsFixedLayer) {
  const auto spheres = pyramid_names(1, 7, 7, 7);
  ASSERT_EQ(spheres.size(), 91u);
  const auto runs = run_config("rigid_settled_pyramid", "0.2", spheres);
  constexpr double r = 0.05;
  for (const auto& s : spheres) {
    const auto p = runs.position(s);
    ASSERT_EQ(p.rows, 21u);
    const int layer = s[1] - '0';
    for (int axis = 0; axis < 2; ++axis) EXPECT_NEAR(p.at(p.rows - 1, axis), p.at(0, axis), 1e-4 * r) << s;
    EXPECT_LE(p.at(p.rows - 1, 2), p.at(0, 2)) << s;
    EXPECT_GE(p.at(p.rows - 1, 2), p.at(0, 2) - 1.05 * (1 + std::sqrt(2.0)) * 1e-3 * r * layer) << s;
  }
}

TEST(RigidScenes, MixedShapesLandOnThePlane) {
  const std::vector<std::string> bodies{"sphere",   "small_sphere", "ellipsoid", "box",
                                        "cylinder", "capsule",      "gem",       "torus"};
  const auto runs = run_config("rigid_mixed_shapes", "0.5", bodies);
  // By t = 0.5 s these rest where their shape says: the box on its 0.03 half extent, the
  // cylinder on an end (half height 0.05), the capsule on its side (radius 0.03), the torus
  // flat (tube radius 0.025); the spheres roll on their radius. The ellipsoid and the gem
  // are still rocking, between their smallest and largest half widths.
  const std::map<std::string, double> rest{{"small_sphere", 0.03}, {"box", 0.03},    {"cylinder", 0.05},
                                           {"capsule", 0.03},      {"torus", 0.025}, {"sphere", 0.05}};
  for (const auto& [b, height] : rest) {
    const auto p = runs.position(b);
    EXPECT_NEAR(p.at(p.rows - 1, 2), height, 0.005 * height) << b;
  }
  for (const char* b : {"box", "cylinder", "capsule", "torus"}) {
    const auto v = runs.velocity(b);
    EXPECT_LT(std::hypot(v.at(v.rows - 1, 0), v.at(v.rows - 1, 1), v.at(v.rows - 1, 2)), 1e-3) << b << " at rest";
  }
  for (const char* b : {"ellipsoid", "gem"}) {
    const auto p = runs.position(b);
    EXPECT_GT(p.at(p.rows - 1, 2), 0.99 * 0.03) << b;
    EXPECT_LT(p.at(p.rows - 1, 2), 0.09) << b << " has not landed";
  }
}

// Guards against: the thin fast plate tunnelling through the plane, or the warning going missing.
TEST(RigidScenes, ThinBoxAtFiftyMetresPerSecondStaysAboveThePlaneAndIsWarnedAbout) {
  const auto runs = run_config("rigid_thin_box", "0.2", {"plate"});
  EXPECT_NE(runs.coupled.output.find("warning: body 1 (plate) may move 0.0501 m per substep"), std::string::npos)
      << runs.coupled.output;
  const auto p = runs.position("plate");
  for (std::size_t row = 0; row < p.rows; ++row) ASSERT_GT(p.at(row, 2), 0.0) << "row " << row;
  EXPECT_NEAR(p.at(p.rows - 1, 2), 0.0025, 0.01 * 0.0025);
}

}  // namespace
}  // namespace cosim::testing
