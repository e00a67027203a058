// `cosim study` end to end: the partitioned oscillator over three levels of window and
// steps, against its exact answer, and the refusals of bad arguments.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <map>
#include <sstream>

#include "tests/integration/cosim_process.hpp"
#include "tests/integration/oscillator_scene.hpp"

namespace cosim::testing {
namespace {

using ::testing::HasSubstr;

// results.csv as rows of column name -> text (the measured expressions hold no commas).
std::vector<std::map<std::string, std::string>> read_csv(const std::filesystem::path& file) {
  std::istringstream in(read_file(file));
  const auto split = [](const std::string& line) {
    std::vector<std::string> fields;
    std::istringstream s(line);
    for (std::string f; std::getline(s, f, ',');) fields.push_back(f);
    if (!line.empty() && line.back() == ',') fields.emplace_back();
    return fields;
  };
  std::string line;
  std::getline(in, line);
  const auto header = split(line);
  std::vector<std::map<std::string, std::string>> rows;
  while (std::getline(in, line)) {
    const auto fields = split(line);
    std::map<std::string, std::string> row;
    for (std::size_t i = 0; i < header.size() && i < fields.size(); ++i) row[header[i]] = fields[i];
    rows.push_back(row);
  }
  return rows;
}

// Serial-implicit coupling with Verlet on both sides is second order in the window
// (oscillator_test.cpp's ObservedOrder): windows of 20, 10 and 5 ms with ten steps each are in
// its asymptotic range for the first mass's position at the end, x1(1 s).
TEST(Study, OscillatorShowsTheSchemesOrderAndTheExtrapolateBeatsTheFinestLevel) {
  OscillatorScene s;
  s.end = 2.0;  // --set cuts it to 1 s on every level
  s.window = 0.02;
  s.dt_mass = s.dt_spring = 0.002;
  const auto dir = scratch_dir("study_oscillator");
  write_file(dir / "oscillator.yaml", s.yaml());
  const auto r = run_cosim({"study", (dir / "oscillator.yaml").string(), "--refine", "2", "--levels", "3", "--measure",
                            "x1=final(body:m1:position.x)", "--order", "2", "--set", "time.end=1.0", "--out",
                            (dir / "study").string()});
  s.end = 1.0;
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::cout << r.output;
  const auto rows = read_csv(dir / "study" / "results.csv");
  ASSERT_EQ(rows.size(), 3u);
  const auto& finest = rows.back();
  const double p = std::stod(finest.at("p"));
  const double extrapolate = std::stod(finest.at("extrapolate"));
  const double exact = s.physics.at(s.end)[0];
  const double finest_error = std::abs(std::stod(finest.at("value")) - exact);
  std::cout << "observed order " << p << ", extrapolate error " << std::abs(extrapolate - exact)
            << ", finest level's error " << finest_error << "\n";
  EXPECT_NEAR(p, 2.0, 0.3);
  EXPECT_LT(std::abs(extrapolate - exact), finest_error);
  EXPECT_EQ(finest.at("coupling.window"), "0.005");
  EXPECT_THAT(r.output, HasSubstr("in the asymptotic range"));
  const std::string report = read_file(dir / "study" / "report.md");
  EXPECT_THAT(report, HasSubstr("| level | coupling.window | participants.mass.dt | participants.spring.dt | value |"));
  EXPECT_THAT(report, HasSubstr("Set on every level: time.end = 1.0."));
  for (const char* f : {"level_1.yaml", "level_3.h5", "level_2.log"}) EXPECT_TRUE(std::filesystem::exists(dir / "study" / f)) << f;
}

// Nothing runs: each mistake is found first, named with its argument, exit status 2.
TEST(Study, BadArgumentsAreNamedAndExitWithStatusTwo) {
  OscillatorScene s;
  const auto dir = scratch_dir("study_arguments");
  const auto scene = (dir / "oscillator.yaml").string();
  write_file(scene, s.yaml());
  const std::string measure = "x1=final(body:m1:position.x)";
  const auto refused = [&](const std::vector<std::string>& args) {
    std::vector<std::string> all{"study", scene, "--out", (dir / "study").string()};
    all.insert(all.end(), args.begin(), args.end());
    const auto r = run_cosim(all);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    return r.output;
  };
  EXPECT_THAT(refused({"--vary", "coupler.window=0.02,0.01", "--measure", measure}),
              HasSubstr("cosim study: --vary coupler.window=0.02,0.01: the scene has no key 'coupler'"));
  EXPECT_THAT(refused({"--vary", "coupling.window=0.02,0.01", "--vary", "participants.mass.dt=0.002", "--measure",
                       measure}),
              HasSubstr("--vary participants.mass.dt=0.002: give at least two values"));
  EXPECT_THAT(refused({"--vary", "coupling.window=0.02,0.01", "--vary", "participants.mass.dt=0.002,0.001,0.0005",
                       "--measure", measure}),
              HasSubstr("every --vary needs one value per level"));
  EXPECT_THAT(refused({"--vary", "coupling.window=0.02,0.01", "--measure", "x1=max(body:m1:position.x"}),
              HasSubstr("--measure x1=max(body:m1:position.x: at the end: expected ')'"));
  EXPECT_THAT(refused({"--vary", "coupling.window=0.02,0.01", "--measure", "x1=max(body:m2:position.x)"}),
              HasSubstr("--measure x1=max(body:m2:position.x): no body 'm2' in the scene (its bodies: m1)"));
  EXPECT_THAT(refused({"--vary", "coupling.window=0.02,0.015", "--measure", measure}),
              HasSubstr("--vary coupling.window=0.02,0.015: level 2 is not a valid scene"));
  EXPECT_THAT(refused({"--refine", "2"}), HasSubstr("nothing to measure"));
  EXPECT_THAT(refused({"--refine", "2", "--measure", measure, "--set", "time.end=0.015"}),
              HasSubstr("cosim study: --set time.end=0.015: the scene is no longer valid"));
  EXPECT_THAT(refused({"--refine", "2", "--measure", measure, "--set", "time.end"}),
              HasSubstr("--set time.end: expected KEY=VALUE"));
}

}  // namespace
}  // namespace cosim::testing
