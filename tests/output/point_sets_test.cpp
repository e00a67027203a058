// Point sets in field frames (an immersed body's surface markers, the tracker's particles):
// a dataset per set per frame beside the cell fields, a Polyvertex grid per set in the
// sidecar, the sets' attributes beside them and node-centred on those grids, the sidecar of
// frames without them as it always was, and the names and values the writer refuses.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <iterator>

#include "tests/output/h5_read.hpp"
#include "coupler/output/run_file.hpp"
#include "tests/output/polyhedral_frame.hpp"
#include "tests/output/temp_dir.hpp"
#include "tests/integration/xdmf_check.hpp"

namespace cosim::output::test {
namespace {

using PointSetsTest = TempDirTest;

RunFile new_run(const std::filesystem::path& path) {
  return RunFile::create(path, RunInfo{"scene: 1\n", "s.yaml", "abc", "0.1.0", 2}, {"ball"}, {"fluid", "tracker"});
}

std::string text_of(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// 2 x 1 x 1 cells with a pressure and a vector.
field::FieldFrame cells_of(std::uint64_t window) {
  const double w = double(window);
  return {field::RectilinearGrid{{{{0.0, 0.5, 1.0}, {0.0, 1.0}, {0.0, 1.0}}}},
          {{"p", 1, {w, w}}, {"u", 3, std::vector<double>(6, 1.0)}}};
}

// A body with window + 1 markers, and one entirely outside the grid.
field::FieldFrame frame_with_bodies(std::uint64_t window) {
  field::FieldFrame frame = cells_of(window);
  field::PointSet ball{"ball", {}};
  for (std::uint64_t i = 0; i <= window; ++i)
    ball.points.insert(ball.points.end(), {0.1 * double(i), 0.5, double(window)});
  frame.point_sets = {std::move(ball), {"outside", {}}};
  return frame;
}

// Every DataItem of the sidecar of run file `h5` names a dataset of the shape it declares;
// returns the sidecar's contents.
testing::XdmfContents checked_sidecar(const std::filesystem::path& h5) {
  std::filesystem::path sidecar = h5;
  const testing::XdmfContents xdmf = testing::read_xdmf(text_of(sidecar.replace_extension(".xmf")));
  ReadFile f(h5);
  for (const testing::XdmfDataItem& item : xdmf.items) {
    EXPECT_EQ(item.file, "run.h5");
    const std::vector<hsize_t> dims = f.dims(item.dataset);
    EXPECT_EQ(std::vector<std::size_t>(dims.begin(), dims.end()), item.dims) << item.dataset;
  }
  return xdmf;
}

TEST_F(PointSetsTest, ADatasetPerSetPerFrameAndAPolyvertexGridInTheSidecar) {
  {
    RunFile run = new_run(file("run.h5"));
    for (std::uint64_t k = 0; k < 3; ++k) run.write_fields("fluid", k, 0.25 * double(k), frame_with_bodies(k));
  }
  ReadFile f(file("run.h5"));
  for (std::uint64_t k = 0; k < 3; ++k) {
    const std::string step = "/fields/fluid/00000" + std::to_string(k);
    EXPECT_EQ(f.dims(step + "/points/ball"), (std::vector<hsize_t>{k + 1, 3})) << step;
    EXPECT_EQ(f.doubles(step + "/points/ball"), frame_with_bodies(k).point_sets[0].points) << step;
    EXPECT_EQ(f.dims(step + "/points/outside"), (std::vector<hsize_t>{0, 3})) << step;
    EXPECT_EQ(f.doubles(step + "/p"), (std::vector<double>{double(k), double(k)})) << step;
  }

  const testing::XdmfContents xdmf = checked_sidecar(file("run.h5"));
  EXPECT_EQ(xdmf.times, (std::vector<double>{0.0, 0.25, 0.5}));
  // The set without points is left out: ParaView's Xdmf2 reader fails on an empty DataItem.
  ASSERT_EQ(xdmf.polyvertices.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(xdmf.polyvertices[k].name, "ball");
    EXPECT_EQ(xdmf.polyvertices[k].elements, k + 1);
    EXPECT_EQ(xdmf.polyvertices[k].points.dataset, "/fields/fluid/00000" + std::to_string(k) + "/points/ball");
  }
  const std::string sidecar = text_of(file("run.xmf"));
  EXPECT_NE(sidecar.find("      <Grid Name=\"/fields/fluid/000001\" GridType=\"Collection\" "
                         "CollectionType=\"Spatial\">\n"
                         "        <Time Value=\"0.25\"/>\n"
                         "        <Grid Name=\"cells\" GridType=\"Uniform\">\n"
                         "          <Topology TopologyType=\"3DRectMesh\" Dimensions=\"2 2 3\"/>\n"),
            std::string::npos);
  EXPECT_NE(sidecar.find("        <Grid Name=\"ball\" GridType=\"Uniform\">\n"
                         "          <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"2\"/>\n"
                         "          <Geometry GeometryType=\"XYZ\">\n"
                         "            <DataItem Dimensions=\"2 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">"
                         "run.h5:/fields/fluid/000001/points/ball</DataItem>\n"
                         "          </Geometry>\n"
                         "        </Grid>\n"
                         "      </Grid>\n"),
            std::string::npos);
  EXPECT_EQ(sidecar.find("outside"), std::string::npos);
}

// Once a participant's frames have point sets every step is a spatial collection, the first
// too (ParaView's Xdmf2 reader takes the first step's kind for all); another participant's
// steps without any stay plain grids.
TEST_F(PointSetsTest, EveryStepOfTheSeriesIsASpatialCollection) {
  {
    RunFile run = new_run(file("run.h5"));
    run.write_fields("fluid", 0, 0.0, cells_of(0));
    run.write_fields("fluid", 1, 0.5, frame_with_bodies(1));
    run.write_fields("tracker", 1, 0.5, polyhedral_frame(1.0));
  }
  const testing::XdmfContents xdmf = checked_sidecar(file("run.h5"));
  ASSERT_EQ(xdmf.polyvertices.size(), 1u);
  EXPECT_EQ(xdmf.polyvertices[0].points.dataset, "/fields/fluid/000001/points/ball");
  const std::string sidecar = text_of(file("run.xmf"));
  EXPECT_NE(sidecar.find("<Grid Name=\"/fields/fluid/000000\" GridType=\"Collection\" CollectionType=\"Spatial\">"),
            std::string::npos);
  EXPECT_NE(sidecar.find("<Grid Name=\"/fields/tracker/000001\" GridType=\"Uniform\">"), std::string::npos);
}

TEST_F(PointSetsTest, BesidePolyhedralCells) {
  {
    RunFile run = new_run(file("run.h5"));
    field::FieldFrame frame = polyhedral_frame(1.0);
    frame.point_sets = {{"dust", {0.5, 0.5, 0.5, 1.5, 0.5, 0.5}}};
    run.write_fields("tracker", 0, 0.0, frame);
  }
  const testing::XdmfContents xdmf = checked_sidecar(file("run.h5"));
  ASSERT_EQ(xdmf.polyvertices.size(), 1u);
  EXPECT_EQ(xdmf.polyvertices[0].elements, 2u);
  EXPECT_NE(text_of(file("run.xmf")).find("          <Topology TopologyType=\"Mixed\" NumberOfElements=\"3\">"),
            std::string::npos);
}

// The sidecar of frames without point sets, byte for byte as before point sets existed.
TEST_F(PointSetsTest, FramesWithoutPointSetsKeepTheirSidecar) {
  {
    RunFile run = new_run(file("run.h5"));
    for (std::uint64_t k = 0; k < 2; ++k) run.write_fields("fluid", k, 0.1 * double(k), cells_of(k));
  }
  const std::string step[2] = {"000000", "000001"};
  const std::string time[2] = {"0", "0.1"};
  std::string expected =
      "<?xml version=\"1.0\" ?>\n"
      "<Xdmf Version=\"3.0\">\n"
      "  <Domain>\n"
      "    <Grid Name=\"fluid\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (int k = 0; k < 2; ++k) {
    const std::string item = "          <DataItem Dimensions=\"";
    const std::string hdf = "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">run.h5:/fields/fluid/";
    expected += "      <Grid Name=\"/fields/fluid/" + step[k] +
                "\" GridType=\"Uniform\">\n"
                "        <Time Value=\"" +
                time[k] +
                "\"/>\n"
                "        <Topology TopologyType=\"3DRectMesh\" Dimensions=\"2 2 3\"/>\n"
                "        <Geometry GeometryType=\"VXVYVZ\">\n" +
                item + "3" + hdf + "grid/x</DataItem>\n" + item + "2" + hdf + "grid/y</DataItem>\n" + item + "2" + hdf +
                "grid/z</DataItem>\n"
                "        </Geometry>\n"
                "        <Attribute Name=\"p\" AttributeType=\"Scalar\" Center=\"Cell\">\n" +
                item + "1 1 2" + hdf + step[k] +
                "/p</DataItem>\n"
                "        </Attribute>\n"
                "        <Attribute Name=\"u\" AttributeType=\"Vector\" Center=\"Cell\">\n" +
                item + "1 1 2 3" + hdf + step[k] +
                "/u</DataItem>\n"
                "        </Attribute>\n"
                "      </Grid>\n";
  }
  expected += "    </Grid>\n  </Domain>\n</Xdmf>\n";
  EXPECT_EQ(text_of(file("run.xmf")), expected);
  EXPECT_FALSE(ReadFile(file("run.h5")).has("/fields/fluid/000001/points"));
}

// Two particles with a velocity, a cell index and a 64-bit state as two 32-bit halves;
// and a set with attributes but no points.
field::FieldFrame frame_with_particles(std::uint64_t window) {
  field::FieldFrame frame = cells_of(window);
  const double w = double(window);
  frame.point_sets = {{"particles",
                       {0.25, 0.5, 0.5, 0.75, 0.5, 0.5},
                       {{"velocity", 3, {1, 2, w, 4, 5, 6}},
                        {"cell", 1, {0, 1}, true},
                        {"state_ball", 2, {4294967295.0, 4294967295.0, 0, w}, true}}},
                      {"none", {}, {{"speed", 1, {}}}},
                      {"markers", {0.5, 0.5, 0.5}}};
  return frame;
}

TEST_F(PointSetsTest, AttributesBesideThePointsAndNodeCentredOnTheirGrid) {
  {
    RunFile run = new_run(file("run.h5"));
    for (std::uint64_t k = 0; k < 2; ++k) run.write_fields("tracker", k, 0.5 * double(k), frame_with_particles(k));
  }
  ReadFile f(file("run.h5"));
  const std::string at = "/fields/tracker/000001/point_attributes/";
  EXPECT_EQ(f.dims(at + "particles/velocity"), (std::vector<hsize_t>{2, 3}));
  EXPECT_EQ(f.doubles(at + "particles/velocity"), (std::vector<double>{1, 2, 1, 4, 5, 6}));
  EXPECT_EQ(f.dims(at + "particles/cell"), (std::vector<hsize_t>{2}));
  // Whole numbers as int64: a state's halves come back exactly.
  EXPECT_EQ(f.values<std::int64_t>(at + "particles/cell", H5T_NATIVE_INT64), (std::vector<std::int64_t>{0, 1}));
  EXPECT_EQ(f.dims(at + "particles/state_ball"), (std::vector<hsize_t>{2, 2}));
  EXPECT_EQ(f.values<std::int64_t>(at + "particles/state_ball", H5T_NATIVE_INT64),
            (std::vector<std::int64_t>{4294967295, 4294967295, 0, 1}));
  EXPECT_EQ(f.dims(at + "none/speed"), (std::vector<hsize_t>{0}));
  EXPECT_FALSE(f.has(at + "markers"));  // a set without attributes has no group
  EXPECT_EQ(f.dims("/fields/tracker/000001/points/particles"), (std::vector<hsize_t>{2, 3}));

  const testing::XdmfContents xdmf = checked_sidecar(file("run.h5"));
  ASSERT_EQ(xdmf.polyvertices.size(), 4u);  // per step particles and markers; "none" has no points
  const testing::XdmfPolyvertex& particles = xdmf.polyvertices[2];
  EXPECT_EQ(particles.name, "particles");
  ASSERT_EQ(particles.attributes.size(), 3u);
  const std::string names[] = {"velocity", "cell", "state_ball"}, types[] = {"Vector", "Scalar", "Matrix"},
                    numbers[] = {"Float", "Int", "Int"};
  const std::vector<std::size_t> dims[] = {{2, 3}, {2}, {2, 2}};
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(particles.attributes[k].name, names[k]);
    EXPECT_EQ(particles.attributes[k].type, types[k]);
    EXPECT_EQ(particles.attributes[k].number_type, numbers[k]);
    EXPECT_EQ(particles.attributes[k].item.dims, dims[k]);
    EXPECT_EQ(particles.attributes[k].item.dataset, at + "particles/" + names[k]);
  }
  EXPECT_TRUE(xdmf.polyvertices[3].attributes.empty());
  EXPECT_NE(text_of(file("run.xmf"))
                .find("          <Attribute Name=\"cell\" AttributeType=\"Scalar\" Center=\"Node\">\n"
                      "            <DataItem Dimensions=\"2\" NumberType=\"Int\" Precision=\"8\" "
                      "Format=\"HDF\">run.h5:/fields/tracker/000000/point_attributes/particles/cell"
                      "</DataItem>\n"
                      "          </Attribute>\n"),
            std::string::npos);
}

std::string write_error(RunFile& run, const field::FieldFrame& frame) {
  try {
    run.write_fields("fluid", 1, 0.1, frame);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  ADD_FAILURE() << "written without error";
  return {};
}

// Refused before anything of the frame is written, with the name in the message.
TEST_F(PointSetsTest, RefusesANameThatIsNoDatasetNameOrComesTwice) {
  RunFile run = new_run(file("run.h5"));
  const auto renamed = [](const std::string& name) {
    field::FieldFrame frame = frame_with_bodies(1);
    frame.point_sets[1].name = name;
    return frame;
  };
  const std::string in = file("run.h5").string() + ": fields of fluid: ";
  EXPECT_EQ(write_error(run, renamed("wall/left")), in + "point set name 'wall/left' cannot name an HDF5 dataset");
  EXPECT_EQ(write_error(run, renamed(".")), in + "point set name '.' cannot name an HDF5 dataset");
  EXPECT_EQ(write_error(run, renamed("")), in + "point set name '' cannot name an HDF5 dataset");
  EXPECT_EQ(write_error(run, renamed(std::string("a\0b", 3))), in + "point set name 'a?b' cannot name an HDF5 dataset");
  EXPECT_EQ(write_error(run, renamed("ball")), in + "point set name 'ball' appears twice");
  field::FieldFrame ragged = frame_with_bodies(1);
  ragged.point_sets[0].points.push_back(1.0);
  EXPECT_EQ(write_error(run, ragged), in + "point set 'ball' has 7 coordinates, not x y z triples");
  field::FieldFrame clash = frame_with_bodies(1);
  clash.fields[0].name = "points";
  EXPECT_EQ(write_error(run, clash),
            file("run.h5").string() + ": field points of fluid: the step's group of that name holds the point sets");
  EXPECT_FALSE(ReadFile(file("run.h5")).has("/fields"));

  run.write_fields("fluid", 1, 0.1, renamed("wall left"));  // any other name will do
  EXPECT_EQ(ReadFile(file("run.h5")).dims("/fields/fluid/000001/points/wall left"), (std::vector<hsize_t>{0, 3}));
}

TEST_F(PointSetsTest, RefusesAttributesThatDoNotFitTheirSet) {
  RunFile run = new_run(file("run.h5"));
  const auto changed = [](const std::function<void(field::PointAttribute&)>& change) {
    field::FieldFrame frame = frame_with_particles(1);
    change(frame.point_sets[0].attributes[1]);  // cell
    return frame;
  };
  const std::string in = file("run.h5").string() + ": fields of fluid: ";
  EXPECT_EQ(write_error(run, changed([](field::PointAttribute& a) { a.name = "a/b"; })),
            in + "attribute name 'a/b' of point set 'particles' cannot name an HDF5 dataset");
  EXPECT_EQ(write_error(run, changed([](field::PointAttribute& a) { a.name = "velocity"; })),
            in + "attribute name 'velocity' appears twice in point set 'particles'");
  EXPECT_EQ(write_error(run, changed([](field::PointAttribute& a) { a.values.pop_back(); })),
            in + "attribute 'cell' of point set 'particles' has 1 values for 2 points of 1 components");
  EXPECT_EQ(write_error(run, changed([](field::PointAttribute& a) { a.components = 0; })),
            in + "attribute 'cell' of point set 'particles' has 0 components");
  EXPECT_EQ(write_error(run, changed([](field::PointAttribute& a) { a.values[1] = 0.5; })),
            in + "attribute 'cell' of point set 'particles' holds 0.500000, not a whole number within +-2^53");
  // Beyond 2^53 a float64 stands for several integers.
  EXPECT_NE(write_error(run, changed([](field::PointAttribute& a) { a.values[1] = 0x1p53 + 2; }))
                .find("holds 9007199254740994"),
            std::string::npos);
  EXPECT_NE(write_error(run, changed([](field::PointAttribute& a) { a.values[1] = std::nan(""); })).find("holds nan"),
            std::string::npos);
  field::FieldFrame clash = frame_with_particles(1);
  clash.fields[0].name = "point_attributes";
  EXPECT_EQ(write_error(run, clash),
            file("run.h5").string() +
                ": field point_attributes of fluid: the step's group of that name holds the point sets' attributes");
  EXPECT_FALSE(ReadFile(file("run.h5")).has("/fields"));
  // The last exact one.
  run.write_fields("fluid", 1, 0.1, changed([](field::PointAttribute& a) { a.values[1] = 0x1p53; }));
  EXPECT_EQ(ReadFile(file("run.h5"))
                .values<std::int64_t>("/fields/fluid/000001/point_attributes/particles/cell", H5T_NATIVE_INT64),
            (std::vector<std::int64_t>{0, std::int64_t{1} << 53}));
}

}  // namespace
}  // namespace cosim::output::test
