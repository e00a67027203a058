// Checkpoints and --resume: the file is cut back to the checkpoint and continues from it.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <utility>

#include "tests/output/h5_read.hpp"
#include "coupler/output/record_shape.hpp"
#include "coupler/output/run_file.hpp"
#include "tests/output/polyhedral_frame.hpp"
#include "tests/output/sample_run.hpp"
#include "tests/output/temp_dir.hpp"

namespace cosim::output::test {
namespace {

using ResumeTest = TempDirTest;

const std::vector<std::string> kBodies{"ball"};
const std::vector<std::string> kParticipants{"fluid", "rigid", "tracer"};
constexpr double kDt = 0.1;  // not exact in binary: times carry rounding, as in a real run

Checkpoint checkpoint_after(std::uint64_t window) {
  const WindowRecord w = sample_window(window, kDt, kBodies.size(), kParticipants);
  Checkpoint c;
  c.next_window = window + 1;
  c.time = w.time;
  c.poses = w.poses;
  c.forces = w.forces;
  c.states = {{"fluid", {1.0, 2.0, 3.0}}, {"rigid", {}}};  // tracer has none
  // A force provider's response tensors in every other checkpoint, none in the rest.
  if (window % 2 == 0)
    for (std::size_t i = 0; i < kResponseWidth * kBodies.size(); ++i) c.responses.push_back(window + 0.01 * i);
  return c;
}

// Writes windows 0..4 with a checkpoint after window 2, as a run killed after window 4.
void write_interrupted_run(const std::filesystem::path& path) {
  RunFile run = RunFile::create(path, RunInfo{"scene: 1\n", "s.yaml", "abc", "0.1.0", 2}, kBodies, kParticipants);
  for (std::uint64_t k = 0; k < 5; ++k) {
    run.append(sample_window(k, kDt, kBodies.size(), kParticipants));
    if (k == 1 || k == 2) run.write_checkpoint(checkpoint_after(k));
  }
  run.set_status("interrupted", 3.0);
}

TEST_F(ResumeTest, CutsSeriesToTheCheckpointAndContinues) {
  const auto path = file("run.h5");
  write_interrupted_run(path);
  {
    RunFile run = RunFile::resume(path, "d1e2f3");
    EXPECT_EQ(run.info().scene_text, "scene: 1\n");
    EXPECT_EQ(run.info().protocol_version, 2);
    const Checkpoint& c = run.checkpoint();
    const Checkpoint expected = checkpoint_after(2);
    EXPECT_EQ(c.next_window, 3u);
    EXPECT_EQ(c.time, expected.time);
    EXPECT_EQ(c.poses, expected.poses);
    EXPECT_EQ(c.forces, expected.forces);
    EXPECT_EQ(c.responses, expected.responses);
    EXPECT_FALSE(c.responses.empty());
    EXPECT_EQ(c.states, expected.states);
    for (std::uint64_t k = c.next_window; k < 7; ++k) {
      run.append(sample_window(k, kDt, kBodies.size(), kParticipants));
    }
  }
  ReadFile f(path);
  EXPECT_EQ(f.string_attribute("/run", "status"), "running");
  EXPECT_EQ(f.double_attribute("/run", "wall_seconds"), 3.0);
  EXPECT_EQ(f.string_attribute("/checkpoint", "current"), "b");  // the second checkpoint
  std::vector<double> times;
  for (std::uint64_t k = 0; k < 7; ++k) times.push_back(sample_window(k, kDt, 1, {}).time);
  EXPECT_EQ(f.doubles("/coupling/time"), times);
  EXPECT_EQ(f.doubles("/bodies/ball/time"), times);
  EXPECT_EQ(f.values<std::uint64_t>("/coupling/window", H5T_NATIVE_UINT64),
            (std::vector<std::uint64_t>{0, 1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(f.dims("/bodies/ball/orientation"), (std::vector<hsize_t>{7, 4}));
  EXPECT_EQ(f.doubles("/bodies/ball/torque")[3 * 3 + 2], slot(3, 0, 18));
  EXPECT_EQ(f.dims("/coupling/participants/tracer/substeps"), (std::vector<hsize_t>{7}));
}

// A 2 x 1 x 1 grid with one scalar whose value is the window, and the tracer's polyhedra,
// written at windows 0..4 around a checkpoint after window 2, as a run killed after window 4.
field::FieldFrame frame_of(std::uint64_t window) {
  return {field::RectilinearGrid{{{{0.0, 0.5, 1.0}, {0.0, 1.0}, {0.0, 1.0}}}},
          {{"p", 1, {double(window), double(window)}}}};
}

void write_interrupted_run_with_fields(const std::filesystem::path& path) {
  RunFile run = RunFile::create(path, RunInfo{"scene: 1\n", "s.yaml", "abc", "0.1.0", 2}, kBodies, kParticipants);
  for (std::uint64_t k = 0; k < 5; ++k) {
    run.append(sample_window(k, kDt, kBodies.size(), kParticipants));
    run.write_fields("fluid", k, kDt * double(k), frame_of(k));
    run.write_fields("tracer", k, kDt * double(k), polyhedral_frame(double(k)));
    if (k == 2) run.write_checkpoint(checkpoint_after(k));
  }
}

std::string file_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The steps after the checkpoint go with the rows; the sidecar names what is left, and the
// resumed run writes those windows anew.
TEST_F(ResumeTest, CutsFieldsToTheCheckpointAndRewritesTheSidecar) {
  const auto path = file("run.h5");
  write_interrupted_run_with_fields(path);
  {
    RunFile run = RunFile::resume(path, "d1e2f3");
    ReadFile f(path);
    EXPECT_TRUE(f.has("/fields/fluid/000003"));  // the checkpoint's own time
    EXPECT_FALSE(f.has("/fields/fluid/000004"));
    const std::string sidecar = file_bytes(file("run.xmf"));
    EXPECT_NE(sidecar.find("/fields/fluid/000003/p"), std::string::npos);
    EXPECT_EQ(sidecar.find("/fields/fluid/000004"), std::string::npos);
    run.write_fields("fluid", 4, 0.4, frame_of(40));
  }
  ReadFile f(path);
  EXPECT_EQ(f.doubles("/fields/fluid/000004/p"), (std::vector<double>{40.0, 40.0}));
  EXPECT_NE(file_bytes(file("run.xmf")).find("/fields/fluid/000004/p"), std::string::npos);
}

// The polyhedral grid is taken up from the file as it was written: the resumed run's
// frames on it are accepted, others refused, and the sidecar keeps its Mixed topology.
TEST_F(ResumeTest, KeepsAPolyhedralGrid) {
  const auto path = file("run.h5");
  write_interrupted_run_with_fields(path);
  RunFile run = RunFile::resume(path, "d1e2f3");
  EXPECT_FALSE(ReadFile(path).has("/fields/tracer/000004"));
  run.write_fields("tracer", 4, 0.4, polyhedral_frame(40.0));
  field::FieldFrame moved = polyhedral_frame(50.0);
  std::get<field::PolyhedralGrid>(moved.grid).vertices.resize(12 * 3);  // the apex gone
  EXPECT_THROW(run.write_fields("tracer", 5, 0.5, moved), std::runtime_error);
  ReadFile f(path);
  EXPECT_EQ(f.doubles("/fields/tracer/000004/density"), (std::vector<double>{40.0, 41.0, 42.0}));
  EXPECT_EQ(f.dims("/fields/tracer/000003/velocity"), (std::vector<hsize_t>{3, 3}));
  const std::string sidecar = file_bytes(file("run.xmf"));
  EXPECT_NE(sidecar.find("<Topology TopologyType=\"Mixed\" NumberOfElements=\"3\">"), std::string::npos);
  // The vector stays a vector: its components are read back from the dataset's shape.
  EXPECT_NE(sidecar.find("<Attribute Name=\"velocity\" AttributeType=\"Vector\" Center=\"Cell\">\n"
                         "          <DataItem Dimensions=\"3 3\" NumberType=\"Float\" Precision=\"8\" "
                         "Format=\"HDF\">run.h5:/fields/tracer/000001/velocity"),
            std::string::npos);
}

// A body's two markers at x = window in every frame, with an index and a speed each (in
// name order, as resume() reads them back), and a body outside the grid.
field::FieldFrame frame_with_bodies(std::uint64_t window) {
  field::FieldFrame frame = frame_of(window);
  const double w = double(window);
  frame.point_sets = {{"ball", {w, 0.5, 0.5, w, 0.25, 0.5}, {{"index", 1, {0, 1}, true}, {"speed", 1, {w, 2 * w}}}},
                      {"cube", {}}};
  return frame;
}

void write_fields_up_to(RunFile& run, std::uint64_t last, std::uint64_t checkpoint_window) {
  for (std::uint64_t k = 0; k <= last; ++k) {
    run.append(sample_window(k, kDt, kBodies.size(), kParticipants));
    run.write_fields("fluid", k, kDt * double(k), frame_with_bodies(k));
    if (k == checkpoint_window) run.write_checkpoint(checkpoint_after(k));
  }
}

// The point sets go with their frames, their attributes too: those after the checkpoint are
// unlinked, those up to it kept, and the sidecar names them as that of a run that stopped
// there would.
TEST_F(ResumeTest, CutsPointSetsWithTheirFrames) {
  const auto path = file("run.h5");
  const RunInfo info{"scene: 1\n", "s.yaml", "abc", "0.1.0", 2};
  {
    RunFile run = RunFile::create(path, info, kBodies, kParticipants);
    write_fields_up_to(run, 4, 2);
  }
  std::filesystem::create_directories(file("stopped"));
  {
    RunFile stopped = RunFile::create(file("stopped") / "run.h5", info, kBodies, kParticipants);
    write_fields_up_to(stopped, 3, 2);
  }
  {
    RunFile run = RunFile::resume(path, "d1e2f3");
    ReadFile f(path);
    for (std::uint64_t k = 0; k <= 3; ++k) {
      const std::string step = "/fields/fluid/00000" + std::to_string(k);
      EXPECT_EQ(f.doubles(step + "/points/ball"), frame_with_bodies(k).point_sets[0].points) << step;
      EXPECT_EQ(f.dims(step + "/points/cube"), (std::vector<hsize_t>{0, 3})) << step;
      EXPECT_EQ(f.doubles(step + "/point_attributes/ball/speed"),
                frame_with_bodies(k).point_sets[0].attributes[1].values);
    }
    EXPECT_FALSE(f.has("/fields/fluid/000004"));
    EXPECT_EQ(file_bytes(file("run.xmf")), file_bytes(file("stopped") / "run.xmf"));
    field::FieldFrame again = frame_with_bodies(4);
    again.point_sets[0].points = {9.0, 9.0, 9.0};
    again.point_sets[0].attributes = {{"index", 1, {7}, true}};
    run.write_fields("fluid", 4, 0.4, again);
  }
  ReadFile f(path);
  EXPECT_EQ(f.doubles("/fields/fluid/000004/points/ball"), (std::vector<double>{9.0, 9.0, 9.0}));
  EXPECT_EQ(f.doubles("/fields/fluid/000004/point_attributes/ball/index"), (std::vector<double>{7.0}));
  EXPECT_FALSE(f.has("/fields/fluid/000004/point_attributes/ball/speed"));
  const std::string sidecar = file_bytes(file("run.xmf"));
  EXPECT_NE(sidecar.find("<Topology TopologyType=\"Polyvertex\" NumberOfElements=\"1\"/>\n"
                         "          <Geometry GeometryType=\"XYZ\">\n"
                         "            <DataItem Dimensions=\"1 3\" NumberType=\"Float\" Precision=\"8\" "
                         "Format=\"HDF\">run.h5:/fields/fluid/000004/points/ball"),
            std::string::npos);
}

// In a frame without point sets "points" may name a cell field: resume() takes it as one.
TEST_F(ResumeTest, KeepsACellFieldNamedPoints) {
  const auto path = file("run.h5");
  {
    RunFile run = RunFile::create(path, RunInfo{}, kBodies, kParticipants);
    field::FieldFrame frame = frame_of(0);
    frame.fields[0].name = "points";
    run.write_fields("fluid", 0, 0.0, frame);
    run.write_checkpoint(checkpoint_after(0));
  }
  const std::string before = file_bytes(file("run.xmf"));
  RunFile run = RunFile::resume(path, "d1e2f3");
  EXPECT_EQ(file_bytes(file("run.xmf")), before);
  EXPECT_NE(before.find("<Attribute Name=\"points\" AttributeType=\"Scalar\""), std::string::npos);
}

// --resume validates what peek() read before resume() changes anything: peek() must leave
// every byte as it was.
TEST_F(ResumeTest, PeekReadsWithoutChangingTheFile) {
  const auto path = file("run.h5");
  write_interrupted_run(path);
  const std::string before = file_bytes(path);
  const RunSummary s = RunFile::peek(path);
  EXPECT_EQ(file_bytes(path), before);
  EXPECT_EQ(s.info.scene_text, "scene: 1\n");
  EXPECT_EQ(s.info.scene_file, "s.yaml");
  EXPECT_EQ(s.info.git_hash, "abc");
  EXPECT_EQ(s.info.cosim_version, "0.1.0");
  EXPECT_EQ(s.info.protocol_version, 2);
  EXPECT_EQ(s.bodies, kBodies);
  EXPECT_EQ(s.participants, kParticipants);
  EXPECT_EQ(s.status, "interrupted");
  EXPECT_EQ(s.wall_seconds, 3.0);
  EXPECT_EQ(s.resumed_by, std::vector<std::string>{});
  EXPECT_TRUE(s.has_checkpoint);
  EXPECT_EQ(s.checkpoint_window, 3u);
  EXPECT_EQ(ReadFile(path).doubles("/coupling/time").size(), 5u);  // not cut back
}

TEST_F(ResumeTest, PeekWithoutCheckpoint) {
  const auto path = file("run.h5");
  RunFile::create(path, RunInfo{}, kBodies, kParticipants).append(sample_window(0, kDt, kBodies.size(), kParticipants));
  const RunSummary s = RunFile::peek(path);
  EXPECT_EQ(s.status, "running");
  EXPECT_FALSE(s.has_checkpoint);
}

// The file keeps the wall time of the whole run, its creator's git hash, and the hash of
// every build that resumed it.
TEST_F(ResumeTest, SessionsAddWallSecondsAndRecordTheirBuild) {
  const auto path = file("run.h5");
  write_interrupted_run(path);  // 3 s
  for (const auto& [hash, seconds] : {std::pair{"def", 2.5}, std::pair{"0123", 1.0}}) {
    RunFile run = RunFile::resume(path, hash);
    EXPECT_EQ(run.info().git_hash, "abc");
    run.set_status("interrupted", seconds);
  }
  {
    RunFile run = RunFile::resume(path, "def");
    run.set_status("running", 0.25);  // a later call replaces this session's time
    run.set_status("finished", 0.5);
  }
  ReadFile f(path);
  EXPECT_EQ(f.double_attribute("/run", "wall_seconds"), 3.0 + 2.5 + 1.0 + 0.5);
  EXPECT_EQ(f.string_attribute("/run", "git_hash"), "abc");
  const std::vector<std::string> builds{"def", "0123", "def"};
  EXPECT_EQ(f.strings("/run/resumed_by"), builds);
  EXPECT_EQ(RunFile::peek(path).resumed_by, builds);
  EXPECT_EQ(RunFile::peek(path).wall_seconds, 7.0);
}

// Files written before resumed_by existed get it at their first resume.
TEST_F(ResumeTest, ResumesAFileWithoutResumedBy) {
  const auto path = file("run.h5");
  write_interrupted_run(path);
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(H5Ldelete(f, "/run/resumed_by", H5P_DEFAULT), 0);
  H5Fclose(f);
  EXPECT_EQ(RunFile::peek(path).resumed_by, std::vector<std::string>{});
  { RunFile run = RunFile::resume(path, "def"); }
  EXPECT_EQ(RunFile::peek(path).resumed_by, std::vector<std::string>{"def"});
}

TEST_F(ResumeTest, ResumeTwiceFromTheSameCheckpoint) {
  const auto path = file("run.h5");
  write_interrupted_run(path);
  { RunFile first = RunFile::resume(path, "d1e2f3"); }
  RunFile second = RunFile::resume(path, "d1e2f3");
  second.append(sample_window(3, kDt, kBodies.size(), kParticipants));
  second = RunFile::create(file("other.h5"), RunInfo{}, {}, {});
  EXPECT_EQ(ReadFile(path).doubles("/coupling/time").size(), 4u);
}

TEST_F(ResumeTest, CheckpointAtStartKeepsNoRows) {
  const auto path = file("run.h5");
  {
    RunFile run = RunFile::create(path, RunInfo{}, kBodies, kParticipants);
    Checkpoint c = checkpoint_after(0);
    c.next_window = 0;
    c.time = 0.0;
    run.write_checkpoint(c);
    run.append(sample_window(0, kDt, kBodies.size(), kParticipants));
    EXPECT_EQ(run.checkpoint().next_window, 0u);
  }
  RunFile run = RunFile::resume(path, "d1e2f3");
  run.append(sample_window(0, kDt, kBodies.size(), kParticipants));
  run = RunFile::create(file("other.h5"), RunInfo{}, {}, {});
  EXPECT_EQ(ReadFile(path).doubles("/coupling/time"), std::vector<double>{kDt});
}

TEST_F(ResumeTest, WithoutCheckpointThrows) {
  const auto path = file("run.h5");
  {
    RunFile::create(path, RunInfo{}, kBodies, kParticipants)
        .append(sample_window(0, kDt, kBodies.size(), kParticipants));
  }
  try {
    RunFile::resume(path, "d1e2f3");
    FAIL() << "resumed a run without checkpoint";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), ("no checkpoint in " + path.string() + ": it cannot be resumed").c_str());
  }
}

// Not HDF5, or HDF5 without /run: both peek() and resume() refuse, naming the file.
TEST_F(ResumeTest, NotARunFileThrowsNamingIt) {
  const auto text = file("scene.yaml");
  std::ofstream(text) << "not hdf5\n";
  const auto other = file("other.h5");
  const auto open_objects = H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL);
  H5Fclose(H5Fcreate(other.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT));
  const std::pair<std::filesystem::path, std::string> cases[] = {
      {text, text.string() + ": not a cosim run file (not HDF5)"},
      {other, other.string() + ": not a cosim run file (no /run group)"}};
  for (const auto& [path, message] : cases) {
    for (const bool peek : {true, false}) {
      try {
        if (peek)
          RunFile::peek(path);
        else
          RunFile::resume(path, "d1e2f3");
        FAIL() << (peek ? "peeked into " : "resumed ") << path;
      } catch (const std::runtime_error& e) {
        EXPECT_EQ(e.what(), message);
      }
    }
  }
  EXPECT_EQ(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL), open_objects);  // nothing left open
}

TEST_F(ResumeTest, MalformedCheckpointKeepsThePreviousOne) {
  const auto path = file("run.h5");
  RunFile run = RunFile::create(path, RunInfo{}, kBodies, kParticipants);
  run.write_checkpoint(checkpoint_after(0));
  Checkpoint bad = checkpoint_after(1);
  bad.states["solid"] = {1.0};
  EXPECT_THROW(run.write_checkpoint(bad), std::runtime_error);
  bad = checkpoint_after(1);
  bad.forces.pop_back();
  EXPECT_THROW(run.write_checkpoint(bad), std::runtime_error);
  EXPECT_EQ(run.checkpoint().next_window, 1u);
  run = RunFile::create(file("other.h5"), RunInfo{}, {}, {});
  EXPECT_EQ(RunFile::resume(path, "d1e2f3").checkpoint().next_window, 1u);
}

void expect_same(const Checkpoint& got, const Checkpoint& want) {
  EXPECT_EQ(got.next_window, want.next_window);
  EXPECT_EQ(got.time, want.time);
  EXPECT_EQ(got.poses, want.poses);
  EXPECT_EQ(got.forces, want.forces);
  EXPECT_EQ(got.states, want.states);
}

// Checkpoints alternate between the slots, within a run and across a resume, and resume()
// always starts from the latest.
TEST_F(ResumeTest, AlternatingCheckpointsResumeToTheLatest) {
  const auto path = file("run.h5");
  for (std::uint64_t k = 0; k < 6; ++k) {
    {
      RunFile run = k == 0 ? RunFile::create(path, RunInfo{}, kBodies, kParticipants) : RunFile::resume(path, "d1e2f3");
      run.append(sample_window(k, kDt, kBodies.size(), kParticipants));
      Checkpoint c = checkpoint_after(k);
      c.states["fluid"].push_back(static_cast<double>(k));  // tells the checkpoints apart
      run.write_checkpoint(c);
    }
    EXPECT_EQ(ReadFile(path).string_attribute("/checkpoint", "current"), k % 2 == 0 ? "a" : "b");
    Checkpoint want = checkpoint_after(k);
    want.states["fluid"].push_back(static_cast<double>(k));
    expect_same(RunFile::resume(path, "d1e2f3").checkpoint(), want);
  }
  EXPECT_EQ(ReadFile(path).doubles("/coupling/time").size(), 6u);
}

// A state may shrink, vanish, come back and grow: each checkpoint reads back exactly, and
// the slots keep the space of their longest state instead of freeing it.
TEST_F(ResumeTest, StatesThatShrinkAndGrowRoundTripExactly) {
  const auto path = file("run.h5");
  // Lengths of fluid's and rigid's states per checkpoint; -1: no state.
  const std::vector<std::pair<int, int>> lengths{{1000, -1}, {10, 7}, {0, 2000}, {-1, 1}, {5000, -1}, {3, 0}};
  for (std::size_t k = 0; k < lengths.size(); ++k) {
    Checkpoint c = checkpoint_after(k);
    c.states.clear();
    for (const auto& [name, n] : {std::pair{"fluid", lengths[k].first}, std::pair{"rigid", lengths[k].second}}) {
      if (n < 0) continue;
      std::vector<double>& state = c.states[name];
      for (int i = 0; i < n; ++i) state.push_back(static_cast<double>(k) + 1e-4 * i);
    }
    {
      RunFile run = k == 0 ? RunFile::create(path, RunInfo{}, kBodies, kParticipants) : RunFile::resume(path, "d1e2f3");
      run.write_checkpoint(c);
    }
    expect_same(RunFile::resume(path, "d1e2f3").checkpoint(), c);
  }
  // Slot a held fluid states of 1000 (and 0, 5000), slot b of 1000 (the first checkpoint
  // fills both), 10 and 3.
  ReadFile f(path);
  EXPECT_EQ(f.dims("/checkpoint/a/participants/fluid/state"), std::vector<hsize_t>{5000});
  EXPECT_EQ(f.dims("/checkpoint/b/participants/fluid/state"), std::vector<hsize_t>{1000});
  EXPECT_EQ(f.double_attribute("/checkpoint/b/participants/fluid/state", "length"), 3.0);
  EXPECT_EQ(f.double_attribute("/checkpoint/a/participants/rigid", "present"), 0.0);
  EXPECT_EQ(f.double_attribute("/checkpoint/a/participants/tracer", "present"), 0.0);
}

// A checkpoint write never frees file space, so the file never gets shorter: HDF5 shrinking
// it is what could leave a file it cannot open after a kill.
TEST_F(ResumeTest, FileSizeNeverDecreasesAcrossCheckpoints) {
  const auto path = file("run.h5");
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> length(-2000, 20000);  // below 0: no state
  RunFile run = RunFile::create(path, RunInfo{}, kBodies, kParticipants);
  std::uintmax_t size = std::filesystem::file_size(path);
  Checkpoint c;
  for (std::uint64_t k = 0; k < 50; ++k) {
    run.append(sample_window(k, kDt, kBodies.size(), kParticipants));
    c = checkpoint_after(k);
    c.states.clear();
    for (const std::string& name : kParticipants) {
      const int n = length(rng);
      if (n >= 0) c.states[name].assign(static_cast<std::size_t>(n), static_cast<double>(k));
    }
    run.write_checkpoint(c);
    const std::uintmax_t now = std::filesystem::file_size(path);
    EXPECT_GE(now, size) << "after checkpoint " << k;
    size = now;
  }
  run = RunFile::create(file("other.h5"), RunInfo{}, {}, {});
  expect_same(RunFile::resume(path, "d1e2f3").checkpoint(), c);
}

}  // namespace
}  // namespace cosim::output::test
