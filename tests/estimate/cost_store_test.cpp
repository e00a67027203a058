#include "coupler/estimate/cost_store.hpp"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace cosim::estimate {
namespace {
namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path p = fs::temp_directory_path() / ("cosim-estimate-" + std::to_string(getpid())) / name;
  fs::remove(p);
  return p;
}

RunRecord record(const std::string& scene, const std::string& build, double cells) {
  RunRecord r;
  r.scene = scene;
  r.build = build;
  r.windows = 10;
  r.iterations = 30;
  r.wall_seconds = 12.5;
  r.disk_bytes = 1.5e5;
  r.programs["fluid"] = {{{"cells", cells}}, {{"cells", cells}}, 30, 9.0, 1.2e8};
  return r;
}

TEST(CostStore, RecordsSurviveASaveAndALoad) {
  const fs::path path = scratch("round-trip.yaml");
  auto store = CostStore::load(path);
  EXPECT_TRUE(store.records().empty());
  store.add(record("/a.yaml", "abc", 1e4));
  store.save();
  const auto loaded = CostStore::load(path);
  ASSERT_EQ(loaded.records().size(), 1u);
  const auto& o = loaded.records()[0].programs.at("fluid");
  EXPECT_EQ(o.per_step.at("cells"), 1e4);
  EXPECT_EQ(o.steps, 30);
  EXPECT_EQ(o.seconds, 9.0);
  EXPECT_EQ(o.peak_bytes, 1.2e8);
  EXPECT_EQ(loaded.records()[0].iterations, 30);
}

TEST(CostStore, ThisBuildsObservationsComeFirst) {
  auto store = CostStore::load(scratch("builds.yaml"));
  store.add(record("/a.yaml", "old", 1e4));
  EXPECT_EQ(store.observations("fluid", "new").size(), 1u);  // only another build's: used
  store.add(record("/a.yaml", "new", 2e4));
  store.add(record("/b.yaml", "new", 3e4));
  const auto same = store.observations("fluid", "new");
  ASSERT_EQ(same.size(), 2u);
  EXPECT_EQ(same[0].per_step.at("cells"), 2e4);
  EXPECT_EQ(store.last_run_of("/a.yaml")->build, "new");
  EXPECT_EQ(store.last_run_of("/c.yaml"), nullptr);
}

TEST(CostStore, AnUnreadableFileIsNamed) {
  const fs::path path = scratch("broken.yaml");
  fs::create_directories(path.parent_path());
  std::ofstream(path) << "runs: [ {scene: 1, build";
  try {
    CostStore::load(path);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
}

// Runs that finish at once (a study's levels side by side) each keep their record: forked
// writers adding to one store at the same time lose none.
TEST(CostStore, WritersAtOnceLoseNoRecord) {
  const fs::path path = scratch("at-once.yaml");
  constexpr int kWriters = 8, kEach = 10;
  std::vector<pid_t> children;
  for (int w = 0; w < kWriters; ++w) {
    const pid_t pid = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      for (int k = 0; k < kEach; ++k)
        CostStore::update(path, [&](CostStore& store) {
          store.add(record("/w" + std::to_string(w) + "-" + std::to_string(k) + ".yaml", "b", 1e4));
        });
      _exit(0);
    }
    children.push_back(pid);
  }
  for (const pid_t pid : children) {
    int status = 0;
    ASSERT_EQ(waitpid(pid, &status, 0), pid);
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  }
  const CostStore store = CostStore::load(path);
  EXPECT_EQ(store.records().size(), static_cast<std::size_t>(kWriters * kEach));
  for (int w = 0; w < kWriters; ++w)
    EXPECT_NE(store.last_run_of("/w" + std::to_string(w) + "-" + std::to_string(kEach - 1) + ".yaml"), nullptr) << w;
}

}  // namespace
}  // namespace cosim::estimate
