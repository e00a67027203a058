// Fields on a polyhedral grid (the tracker's): the grid once, every step, the Mixed
// topology in the sidecar, and the frames the writer refuses. Read back with the C API.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <fstream>
#include <iterator>
#include <variant>

#include "tests/output/h5_read.hpp"
#include "coupler/output/run_file.hpp"
#include "tests/output/polyhedral_frame.hpp"
#include "tests/output/temp_dir.hpp"

namespace cosim::output::test {
namespace {

using PolyhedralFieldsTest = TempDirTest;

RunFile new_run(const std::filesystem::path& path) {
  return RunFile::create(path, RunInfo{"scene: 1\n", "s.yaml", "abc", "0.1.0", 2}, {"ball"}, {"tracker"});
}

std::string text_of(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::size_t occurrences(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST_F(PolyhedralFieldsTest, WritesTheGridOnceAndEveryStep) {
  const field::FieldFrame first = polyhedral_frame(1.0);
  {
    RunFile run = new_run(file("run.h5"));
    run.write_fields("tracker", 0, 0.0, first);
    run.write_fields("tracker", 10, 0.5, polyhedral_frame(2.0));
  }
  const auto& grid = std::get<field::PolyhedralGrid>(first.grid);
  ReadFile f(file("run.h5"));
  EXPECT_EQ(f.dims("/fields/tracker/grid/vertices"), (std::vector<hsize_t>{13, 3}));
  EXPECT_EQ(f.doubles("/fields/tracker/grid/vertices"), grid.vertices);
  EXPECT_EQ(f.values<std::int64_t>("/fields/tracker/grid/topology", H5T_NATIVE_INT64), grid.topology);
  EXPECT_EQ(f.double_attribute("/fields/tracker/grid", "cells"), 3.0);
  EXPECT_EQ(f.double_attribute("/fields/tracker/000010", "time"), 0.5);
  EXPECT_EQ(f.dims("/fields/tracker/000010/density"), (std::vector<hsize_t>{3}));
  EXPECT_EQ(f.doubles("/fields/tracker/000010/density"), (std::vector<double>{2, 3, 4}));
  EXPECT_EQ(f.dims("/fields/tracker/000000/velocity"), (std::vector<hsize_t>{3, 3}));
  EXPECT_EQ(f.doubles("/fields/tracker/000000/velocity"), (std::vector<double>{1, 0, -1, 1, 1, -1, 1, 2, -1}));

  const std::string sidecar = text_of(file("run.xmf"));
  EXPECT_EQ(occurrences(sidecar, "<Topology TopologyType=\"Mixed\" NumberOfElements=\"3\">"), 2u);
  EXPECT_EQ(occurrences(sidecar, "run.h5:/fields/tracker/grid/topology</DataItem>"), 2u);
  EXPECT_NE(sidecar.find("Dimensions=\"" + std::to_string(grid.topology.size()) + "\" NumberType=\"Int\""),
            std::string::npos);
  EXPECT_NE(sidecar.find("Dimensions=\"13 3\""), std::string::npos);
  EXPECT_NE(sidecar.find("Dimensions=\"3 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">"
                         "run.h5:/fields/tracker/000010/velocity"),
            std::string::npos);
  EXPECT_EQ(sidecar.find("3DRectMesh"), std::string::npos);
}

TEST_F(PolyhedralFieldsTest, BothKindsOfGridInOneFile) {
  {
    RunFile run = new_run(file("run.h5"));
    run.write_fields("tracker", 0, 0.0, polyhedral_frame(1.0));
    run.write_fields("fluid", 0, 0.0,
                     {field::RectilinearGrid{{{{0.0, 1.0}, {0.0, 1.0}, {0.0, 2.0}}}}, {{"p", 1, {7.0}}}});
  }
  ReadFile f(file("run.h5"));
  EXPECT_EQ(f.doubles("/fields/fluid/000000/p"), (std::vector<double>{7.0}));
  EXPECT_EQ(f.dims("/fields/tracker/000000/density"), (std::vector<hsize_t>{3}));
  const std::string sidecar = text_of(file("run.xmf"));
  EXPECT_EQ(occurrences(sidecar, "TopologyType=\"Mixed\""), 1u);
  EXPECT_EQ(occurrences(sidecar, "TopologyType=\"3DRectMesh\""), 1u);
}

std::string write_error(RunFile& run, std::uint64_t window, const field::FieldFrame& frame) {
  try {
    run.write_fields("tracker", window, 0.1 * double(window), frame);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  ADD_FAILURE() << "written without error";
  return {};
}

TEST_F(PolyhedralFieldsTest, RefusesAnotherGridOrABrokenOne) {
  RunFile run = new_run(file("run.h5"));
  field::FieldFrame broken = polyhedral_frame(1.0);
  std::get<field::PolyhedralGrid>(broken.grid).topology.back() = 13;
  EXPECT_NE(write_error(run, 0, broken).find("fields of tracker: cell 2 of the topology names vertex 13 of 13"),
            std::string::npos);
  field::FieldFrame short_field = polyhedral_frame(1.0);
  short_field.fields[0].values.pop_back();
  EXPECT_NE(write_error(run, 0, short_field).find("field density of tracker: 2 values do not fit the grid"),
            std::string::npos);

  run.write_fields("tracker", 0, 0.0, polyhedral_frame(1.0));
  field::FieldFrame fewer = polyhedral_frame(1.0);  // the hexahedra without the tetrahedron
  auto& grid = std::get<field::PolyhedralGrid>(fewer.grid);
  grid.topology.resize(grid.topology.size() - 18);
  grid.cells = 2;
  for (field::CellField& f : fewer.fields) f.values.resize(2 * static_cast<std::size_t>(f.components));
  EXPECT_NE(write_error(run, 1, fewer).find("fields of tracker: the grid changed"), std::string::npos);
  const field::FieldFrame rectilinear{field::RectilinearGrid{{{{0.0, 1.0}, {0.0, 1.0}, {0.0, 1.0, 2.0, 3.0}}}},
                                      {{"p", 1, {1, 2, 3}}}};
  EXPECT_NE(write_error(run, 1, rectilinear).find("fields of tracker: the grid changed"), std::string::npos);
}

}  // namespace
}  // namespace cosim::output::test
