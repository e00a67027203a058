// Each program's share of a run's windows and its peak memory, read back from the run file.
#include "coupler/output/program_costs.hpp"

#include <gtest/gtest.h>

#include "coupler/output/run_file.hpp"
#include "tests/output/temp_dir.hpp"

namespace cosim::output::test {
namespace {

using ProgramCostsTest = TempDirTest;

// Two windows of 1 s and 3 s; the fluid takes 0.5 and 2 s of them, the rigid bodies 0.25
// and 0.5 s.
std::filesystem::path two_windows(const std::filesystem::path& path) {
  RunFile run = RunFile::create(path, RunInfo{}, {}, {"fluid", "rigid"});
  const double window[] = {1.0, 3.0}, fluid[] = {0.5, 2.0}, rigid[] = {0.25, 0.5};
  for (int k = 0; k < 2; ++k) {
    WindowRecord w;
    w.window = static_cast<std::uint64_t>(k);
    w.time = 0.1 * (k + 1);
    w.wall_seconds = window[k];
    w.participant_wall_seconds = {{"fluid", fluid[k]}, {"rigid", rigid[k]}};
    w.participant_substeps = {{"fluid", 1.0}, {"rigid", 1.0}};
    w.participant_field_bytes = {{"fluid", 0.0}, {"rigid", 0.0}};
    run.append(w);
  }
  run.set_peak_bytes({{"fluid", 2.0e9}, {"rigid", 1.0e8}});
  run.set_peak_bytes({{"fluid", 1.5e9}});  // a later, smaller session keeps the larger peak
  return path;
}

TEST_F(ProgramCostsTest, SharesOfTheWindowsAndPeaksOneAfterAnother) {
  const auto costs = program_costs(two_windows(file("run.h5")), true);
  ASSERT_EQ(costs.size(), 3u);
  EXPECT_EQ(costs[0].name, "fluid");
  EXPECT_DOUBLE_EQ(costs[0].share, 2.5 / 4);
  EXPECT_DOUBLE_EQ(costs[0].peak_bytes, 2.0e9);
  EXPECT_DOUBLE_EQ(costs[1].share, 0.75 / 4);
  EXPECT_DOUBLE_EQ(costs[1].peak_bytes, 1.0e8);
  EXPECT_EQ(costs[2].name, "coupler");
  EXPECT_DOUBLE_EQ(costs[2].share, (0.25 + 0.5) / 4);
  EXPECT_LT(costs[2].peak_bytes, 0);  // the coupler's own memory is not in the file
}

// Side by side, the coupler has what the longest participant leaves of each window.
TEST_F(ProgramCostsTest, SideBySideTheLongestCounts) {
  const auto costs = program_costs(two_windows(file("run.h5")), false);
  ASSERT_EQ(costs.size(), 3u);
  EXPECT_DOUBLE_EQ(costs[2].share, (0.5 + 1.0) / 4);
}

TEST_F(ProgramCostsTest, NoPeakBeforeASessionFinished) {
  const auto path = file("run.h5");
  RunFile::create(path, RunInfo{}, {}, {"fluid"});
  const auto costs = program_costs(path, true);
  ASSERT_EQ(costs.size(), 2u);
  EXPECT_LT(costs[0].peak_bytes, 0);
  EXPECT_EQ(costs[0].share, 0);
}

TEST_F(ProgramCostsTest, ErrorsNameTheFile) {
  try {
    program_costs(file("absent.h5"), true);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("absent.h5"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace cosim::output::test
