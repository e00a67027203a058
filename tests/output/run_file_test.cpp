// Writing a run: what create() and append() put in the file, read back with the C API.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <hdf5.h>
#include <mpi.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <regex>

#include "tests/output/h5_read.hpp"
#include "coupler/output/h5_handle.hpp"
#include "coupler/output/h5_values.hpp"
#include "coupler/output/run_file.hpp"
#include "coupler/output/series.hpp"
#include "tests/output/sample_run.hpp"
#include "tests/output/temp_dir.hpp"

namespace cosim::output::test {
namespace {

using RunFileTest = TempDirTest;

const std::vector<std::string> kBodies{"ball", "box"};
const std::vector<std::string> kParticipants{"fluid", "rigid"};

RunInfo sample_info() {
  RunInfo info;
  info.scene_text = "coupling:\n  window: 0.01\n" + std::string(100000, '#');  // > 64 KiB
  info.scene_file = "configs/oscillator.yaml";
  info.git_hash = "cec74a8";
  info.cosim_version = "0.1.0";
  info.protocol_version = 3;
  return info;
}

std::size_t open_hdf5_objects() { return static_cast<std::size_t>(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL)); }

TEST_F(RunFileTest, AppendedWindowsReadBackExactly) {
  const auto path = file("run.h5");
  constexpr std::uint64_t kWindows = 300;  // more than one 256-row chunk
  {
    RunFile run = RunFile::create(path, sample_info(), kBodies, kParticipants);
    for (std::uint64_t k = 0; k < kWindows; ++k) {
      run.append(sample_window(k, 0.01, kBodies.size(), kParticipants));
    }
  }
  ReadFile f(path);
  EXPECT_EQ(f.dims("/coupling/time"), (std::vector<hsize_t>{kWindows}));
  const auto windows = f.values<std::uint64_t>("/coupling/window", H5T_NATIVE_UINT64);
  const auto time = f.doubles("/coupling/time");
  const auto iterations = f.values<int>("/coupling/iterations", H5T_NATIVE_INT);
  const auto residual = f.doubles("/coupling/residual");
  const auto wall = f.doubles("/coupling/wall_seconds");
  for (std::uint64_t k = 0; k < kWindows; ++k) {
    const WindowRecord w = sample_window(k, 0.01, kBodies.size(), kParticipants);
    EXPECT_EQ(windows[k], k);
    EXPECT_EQ(time[k], w.time);
    EXPECT_EQ(iterations[k], w.iterations);
    EXPECT_EQ(residual[k], w.residual);
    EXPECT_EQ(wall[k], w.wall_seconds);
  }

  // Each body quantity is a column slice of the 13-wide pose row or the 6-wide force row.
  const std::vector<std::pair<std::string, std::size_t>> slices{
      {"position", 0}, {"orientation", 3}, {"velocity", 7}, {"angular_velocity", 10}, {"force", 13}, {"torque", 16}};
  for (std::size_t b = 0; b < kBodies.size(); ++b) {
    const std::string group = "/bodies/" + kBodies[b] + "/";
    EXPECT_EQ(f.doubles(group + "time"), time);
    for (std::size_t s = 0; s < slices.size(); ++s) {
      const auto& [name, first] = slices[s];
      const std::size_t width = (s + 1 < slices.size() ? slices[s + 1].second : 19) - first;
      ASSERT_EQ(f.dims(group + name), (std::vector<hsize_t>{kWindows, width})) << name;
      const auto values = f.doubles(group + name);
      for (std::uint64_t k = 0; k < kWindows; ++k) {
        for (std::size_t c = 0; c < width; ++c) {
          ASSERT_EQ(values[k * width + c], slot(k, b, first + c)) << group << name;
        }
      }
    }
  }
  for (std::size_t p = 0; p < kParticipants.size(); ++p) {
    const std::string group = "/coupling/participants/" + kParticipants[p] + "/";
    EXPECT_EQ(f.doubles(group + "wall_seconds"), std::vector<double>(kWindows, 0.1 * static_cast<double>(p + 1)));
    EXPECT_EQ(f.doubles(group + "substeps"), std::vector<double>(kWindows, static_cast<double>(p + 2)));
  }
}

TEST_F(RunFileTest, RunGroupDescribesTheRun) {
  const auto path = file("run.h5");
  const RunInfo info = sample_info();
  {
    RunFile run = RunFile::create(path, info, kBodies, kParticipants);
    EXPECT_EQ(run.info().git_hash, info.git_hash);
    run.set_status("finished", 12.5);
  }
  ReadFile f(path);
  EXPECT_EQ(f.string_attribute("/run", "status"), "finished");
  EXPECT_EQ(f.double_attribute("/run", "wall_seconds"), 12.5);
  EXPECT_EQ(f.string_attribute("/run", "scene_file"), info.scene_file);
  EXPECT_EQ(f.string_attribute("/run", "git_hash"), info.git_hash);
  EXPECT_EQ(f.string_attribute("/run", "cosim_version"), info.cosim_version);
  EXPECT_EQ(f.double_attribute("/run", "protocol_version"), 3.0);
  EXPECT_TRUE(
      std::regex_match(f.string_attribute("/run", "started"), std::regex(R"(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ)")));
  EXPECT_EQ(f.dims("/run/scene_text"), std::vector<hsize_t>{});  // scalar
  EXPECT_EQ(f.text("/run/scene_text"), info.scene_text);
}

// Guards against: the body names as an attribute in the group's header, whose messages
// hold 64 KiB, so that a scene of some thousands of bodies could not create its run file.
TEST_F(RunFileTest, TenThousandBodiesAreNamed) {
  const auto path = file("run.h5");
  std::vector<std::string> bodies;
  for (int i = 0; i < 10000; ++i) bodies.push_back("sphere" + std::to_string(i));
  {
    RunFile run = RunFile::create(path, sample_info(), bodies, kParticipants);
    run.set_status("finished", 1.0);
  }
  EXPECT_EQ(RunFile::peek(path).bodies, bodies);
}

TEST_F(RunFileTest, NoBodiesNoParticipants) {
  const auto path = file("run.h5");
  {
    RunFile run = RunFile::create(path, RunInfo{}, {}, {});
    run.append(sample_window(0, 0.5, 0, {}));
  }
  ReadFile f(path);
  EXPECT_EQ(f.doubles("/coupling/time"), std::vector<double>{0.5});
  EXPECT_TRUE(f.has("/bodies"));
}

TEST_F(RunFileTest, MalformedWindowIsRejectedWithoutPartialRow) {
  const auto path = file("run.h5");
  RunFile run = RunFile::create(path, RunInfo{}, kBodies, kParticipants);
  run.append(sample_window(0, 0.1, kBodies.size(), kParticipants));

  WindowRecord short_poses = sample_window(1, 0.1, kBodies.size(), kParticipants);
  short_poses.poses.pop_back();
  WindowRecord stranger = sample_window(1, 0.1, kBodies.size(), kParticipants);
  stranger.participant_substeps["solid"] = 1.0;
  for (const WindowRecord& bad : {short_poses, stranger}) {
    try {
      run.append(bad);
      FAIL() << "accepted a malformed window";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(path.string() + ": window 1"), std::string::npos) << e.what();
    }
  }
  run.append(sample_window(1, 0.1, kBodies.size(), kParticipants));
  run = RunFile::create(file("other.h5"), RunInfo{}, {}, {});  // closes run.h5
  EXPECT_EQ(ReadFile(path).doubles("/coupling/time"), (std::vector<double>{0.1, 0.2}));
}

TEST_F(RunFileTest, MissingParticipantValuesAreNan) {
  const auto path = file("run.h5");
  {
    RunFile run = RunFile::create(path, RunInfo{}, {}, kParticipants);
    WindowRecord w = sample_window(0, 0.1, 0, kParticipants);
    w.participant_substeps.erase("rigid");
    run.append(w);
  }
  EXPECT_TRUE(std::isnan(ReadFile(path).doubles("/coupling/participants/rigid/substeps")[0]));
}

TEST_F(RunFileTest, BadNamesAreRejected) {
  for (const std::vector<std::string>& names : {std::vector<std::string>{"a/b"}, {""}, {"."}, {"ball", "ball"}}) {
    EXPECT_THROW(RunFile::create(file("run.h5"), RunInfo{}, names, {}), std::runtime_error);
    EXPECT_THROW(RunFile::create(file("run.h5"), RunInfo{}, {}, names), std::runtime_error);
  }
}

TEST_F(RunFileTest, ErrorsNameTheFile) {
  const auto path = file("missing") / "run.h5";
  try {
    RunFile::create(path, RunInfo{}, {}, {});
    FAIL() << "created a file in a missing directory";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()).rfind(path.string() + ": create file", 0), 0u) << e.what();
  }
}

TEST_F(RunFileTest, ClosesEverything) {
  const std::size_t before = open_hdf5_objects();
  {
    RunFile run = RunFile::create(file("run.h5"), sample_info(), kBodies, kParticipants);
    run.append(sample_window(0, 0.1, kBodies.size(), kParticipants));
    run.write_checkpoint(Checkpoint{1, 0.1, std::vector<double>(26), std::vector<double>(12), {}});
    EXPECT_GT(open_hdf5_objects(), before);
    RunFile moved = std::move(run);
    moved.set_status("finished", 1.0);
  }
  EXPECT_EQ(open_hdf5_objects(), before);
  EXPECT_THROW(RunFile::resume(file("not-there.h5"), "d1e2f3"), std::runtime_error);
  EXPECT_EQ(open_hdf5_objects(), before);
  RunFile::peek(file("run.h5"));
  EXPECT_EQ(open_hdf5_objects(), before);
}

// What a program started from this process finds open: its /proc/self/fd listing.
std::string descriptors_of_a_child() {
  FILE* ls = popen("ls -l /proc/self/fd", "r");  // fork and exec of /bin/sh, as a launcher
  if (ls == nullptr) throw std::runtime_error("popen failed");
  std::string listing;
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, ls)) > 0;) listing.append(buffer, n);
  pclose(ls);
  return listing;
}

// The coupler starts its participants while the file is open: they must not inherit its
// descriptor, which would share HDF5's lock and keep --resume out while they live.
TEST_F(RunFileTest, ProgramsStartedMeanwhileDoNotInheritTheFile) {
  const auto path = file("run.h5");
  const auto named = [&](const std::string& listing) {
    return listing.find("-> " + path.string() + "\n") != std::string::npos;
  };
  RunFile run = RunFile::create(path, sample_info(), kBodies, kParticipants);
  const int plain = open(path.c_str(), O_RDONLY);  // shows that the listing would name it
  ASSERT_GE(plain, 0);
  EXPECT_TRUE(named(descriptors_of_a_child()));
  close(plain);
  EXPECT_FALSE(named(descriptors_of_a_child())) << "after create()";
  run.write_checkpoint(Checkpoint{1, 0.1, std::vector<double>(26), std::vector<double>(12), {}});
  run = RunFile::create(file("other.h5"), RunInfo{}, {}, {});
  run = RunFile::resume(path, "d1e2f3");
  EXPECT_FALSE(named(descriptors_of_a_child())) << "after resume()";
}

// The coupler is a serial program linked against the parallel HDF5: it must work without
// MPI_Init.
TEST_F(RunFileTest, WorksWithoutMpiInit) {
  int initialized = 1;
  MPI_Initialized(&initialized);
  ASSERT_EQ(initialized, 0);
  {
    RunFile run = RunFile::create(file("run.h5"), RunInfo{}, kBodies, kParticipants);
    run.append(sample_window(0, 0.1, kBodies.size(), kParticipants));
  }
  EXPECT_EQ(ReadFile(file("run.h5")).doubles("/coupling/time").size(), 1u);
}

// A series is a 1-d or 2-d dataset: a 3-d one (a box's cell field) is refused by name,
// its dimensions never read into a series' two.
TEST_F(RunFileTest, ASeriesIsNotAThreeDimensionalDataset) {
  Handle h5(H5Fcreate(file("cube.h5").c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose, "create");
  const std::vector<double> values(4 * 3 * 2 * 5, 1.0);
  write_array(h5.get(), "cube", {4, 3, 2, 5}, values.data());
  try {
    Series::open(h5.get(), "cube");
    FAIL() << "opened a 4-d dataset as a series";
  } catch (const ObjectError& e) {
    EXPECT_NE(std::string(e.what()).find("cube is not a 1-d or 2-d dataset"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace cosim::output::test
