// `generate: file`: bodies at the poses of a CSV table, or where a run file's last row left
// them. The scene is `dir/scene.yaml`: `head`, then `bodies:` at line 4, the entry from line 5.
#include <gtest/gtest.h>

#include <fstream>

#include "coupler/output/run_file.hpp"
#include "tests/output/temp_dir.hpp"
#include "tests/scene/errors.hpp"

namespace cosim::scene {
namespace {

class PoseFile : public output::test::TempDirTest {
 protected:
  void write(const std::string& name, const std::string& text) const { std::ofstream(file(name)) << text; }

  // The entry reading `name` (its `file` key is line 9), and `extra` keys after it.
  std::string scene(const std::string& name, const std::string& extra = "") const {
    return head +
           "bodies:\n  - generate: file\n    name: \"g{}\"\n    shape: {type: sphere, radius: 0.01}\n"
           "    material: {density: 1000}\n    file: " +
           name + "\n" + extra;
  }
  Scene load(const std::string& text) const { return load_scene_from_string(text, file("scene.yaml")); }
  std::string error(const std::string& text) const {
    return thrown([&] { load(text); });
  }
  // The scene's path in messages, as the user gave it.
  std::string where(int line) const { return file("scene.yaml").string() + ":" + std::to_string(line) + ": "; }
};

TEST_F(PoseFile, CsvWithHeaderCommentsAndBlankLines) {
  write("bed.csv", "x, y, z\n# the lowest layer\n0.1, 0.2, 0.3\n\n0.4,0.5,0.6\r\n");
  const Scene s = load(scene("bed.csv", "    velocity: [0, 0, -1]\n"));
  ASSERT_EQ(s.bodies.size(), 2u);
  EXPECT_EQ(s.bodies[0].name, "g0");
  EXPECT_EQ(s.bodies[0].position, (Vec3{0.1, 0.2, 0.3}));
  EXPECT_EQ(s.bodies[1].position, (Vec3{0.4, 0.5, 0.6}));
  EXPECT_EQ(s.bodies[1].velocity, (Vec3{0, 0, -1}));  // the entry's, as the file gives none
  ASSERT_EQ(s.generators.size(), 1u);
  EXPECT_EQ(s.generators[0].kind, Generator::File);
}

TEST_F(PoseFile, CsvColumnsGiveOrientationAndVelocity) {
  write("seven.csv", "0.5, 0.5, 0.5, 0, 0, 0, 1.0000004\n");
  const Scene seven = load(scene("seven.csv"));
  EXPECT_EQ(seven.bodies[0].orientation, (Quat{0, 0, 0, 1}));  // normalised
  EXPECT_EQ(seven.bodies[0].velocity, (Vec3{0, 0, 0}));
  write("six.csv", "0.5, 0.5, 0.5, 1, 2, 3\n");
  EXPECT_EQ(load(scene("six.csv")).bodies[0].velocity, (Vec3{1, 2, 3}));
  write("ten.csv", "0.5, 0.5, 0.5, 1, 0, 0, 0, 1, 2, 3\n");
  const Scene ten = load(scene("ten.csv", "    orientation: [0, 1, 0, 0]\n"));
  EXPECT_EQ(ten.bodies[0].orientation, (Quat{1, 0, 0, 0}));  // the file's, over the entry's
  EXPECT_EQ(ten.bodies[0].velocity, (Vec3{1, 2, 3}));
}

TEST_F(PoseFile, BadCsvLinesNameTheFileAndTheLine) {
  const std::string key = where(9) + "bodies[0].file = bed.csv: ";
  write("bed.csv", "x,y,z\n0.1, 0.2, 0.3\n0.1, abc, 0.3\n");
  EXPECT_EQ(error(scene("bed.csv")), key + "line 3: 'abc' is not a number");
  write("bed.csv", "0.1, 0.2\n");
  EXPECT_EQ(error(scene("bed.csv")),
            key + "line 1: 2 numbers; expected 3, 6, 7 or 10 numbers (x,y,z[,qw,qx,qy,qz][,vx,vy,vz])");
  write("bed.csv", "0.1, 0.2, 0.3\n0.1, 0.2, 0.3, 1, 0, 0, 0\n");
  EXPECT_EQ(error(scene("bed.csv")), key + "line 2: 7 numbers where the lines before have 3");
  write("bed.csv", "0.1, 0.2, 0.3, 1, 1, 0, 0\n");
  EXPECT_EQ(error(scene("bed.csv")), key + "line 1: qw,qx,qy,qz not a unit quaternion (norm 1.41421)");
  write("bed.csv", "0.1, 0.2, 0.995\n");
  EXPECT_EQ(error(scene("bed.csv")), key +
                                         "line 1: the body (extent [0.09, 0.19, 0.985] .. [0.11, 0.21, 1.005]) is "
                                         "outside the domain [0, 0, 0] .. [1, 1, 1]");
  write("bed.csv", "x,y,z\n# nothing yet\n");
  EXPECT_EQ(error(scene("bed.csv")), key + "no bodies in the file (no line of numbers)");
  // A first line with a typo is no header: it is reported, not skipped.
  write("bed.csv", "0.1x, 0.2, 0.3\n");
  EXPECT_EQ(error(scene("bed.csv")), key + "line 1: '0.1x' is not a number");
}

TEST_F(PoseFile, MissingFileAndUnknownKind) {
  EXPECT_EQ(error(scene("none.csv")),
            where(9) + "bodies[0].file = none.csv: no such file: " + file("none.csv").string());
  write("bed.txt", "0.1, 0.2, 0.3\n");
  EXPECT_EQ(error(scene("bed.txt")),
            where(9) + "bodies[0].file = bed.txt: expected a .csv table or a cosim run file (.h5)");
}

// A run file as the coupler writes it, with bodies a and b and two windows; the second
// leaves a at (0.1, 0.2, 0.3) turned half about z, b at (0.6, 0.7, 0.8).
void write_run(const std::filesystem::path& path, const std::vector<std::string>& bodies, int windows) {
  auto run = output::RunFile::create(path, {"scene", "s.yaml", "hash", "0.1", 1}, bodies, {});
  for (int k = 0; k < windows; ++k) {
    output::WindowRecord w;
    w.window = static_cast<std::uint64_t>(k);
    w.time = 0.1 * (k + 1);
    const double shift = k == windows - 1 ? 0 : 0.05;  // the earlier rows are elsewhere
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      const double at = 0.1 + 0.5 * static_cast<double>(b) + shift;
      const std::vector<double> pose{at, at + 0.1, at + 0.2, b == 0 ? 0.0 : 1.0, 0, 0, b == 0 ? 1.0 : 0.0, 1, 1, 1,
                                     1,  1,        1};
      w.poses.insert(w.poses.end(), pose.begin(), pose.end());
      w.forces.insert(w.forces.end(), 6, 0.0);
    }
    run.append(w);
  }
}

TEST_F(PoseFile, RunFileGivesItsBodiesWhereTheLastRowLeftThem) {
  write_run(file("settled.h5"), {"a", "b"}, 2);
  const Scene s = load(scene("settled.h5"));
  ASSERT_EQ(s.bodies.size(), 2u);
  EXPECT_EQ(s.bodies[0].name, "g0");
  EXPECT_EQ(s.bodies[0].position, (Vec3{0.1, 0.1 + 0.1, 0.1 + 0.2}));
  EXPECT_EQ(s.bodies[0].orientation, (Quat{0, 0, 0, 1}));
  EXPECT_EQ(s.bodies[1].position, (Vec3{0.6, 0.6 + 0.1, 0.6 + 0.2}));
  EXPECT_EQ(s.bodies[1].orientation, (Quat{1, 0, 0, 0}));
  EXPECT_EQ(s.bodies[1].velocity, (Vec3{0, 0, 0}));  // poses only: a settled bed starts at rest
}

TEST_F(PoseFile, RunFilesWithoutBodiesOrRowsOrNoRunFileAtAll) {
  write_run(file("empty.h5"), {}, 1);
  EXPECT_EQ(error(scene("empty.h5")), where(9) + "bodies[0].file = empty.h5: the run file has no bodies");
  write_run(file("fresh.h5"), {"a"}, 0);
  EXPECT_EQ(error(scene("fresh.h5")),
            where(9) + "bodies[0].file = fresh.h5: " + file("fresh.h5").string() + ": no row written yet");
  write("text.h5", "not HDF5\n");
  EXPECT_EQ(error(scene("text.h5")),
            where(9) + "bodies[0].file = text.h5: " + file("text.h5").string() + ": not a cosim run file (not HDF5)");
}

TEST_F(PoseFile, TheScenesOwnOutputFileIsRefused) {
  write_run(file("run.h5"), {"a"}, 1);
  EXPECT_EQ(error("output: {file: " + file("run.h5").string() + "}\n" + scene("run.h5")),
            where(10) +
                "bodies[0].file = run.h5: is the scene's output.file, which a run of this scene overwrites "
                "before its participants read it");
}

}  // namespace
}  // namespace cosim::scene
