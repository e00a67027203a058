// cosim-fluid --standalone writes cell-centred fields and an XDMF sidecar naming them.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "tests/integration/cosim_process.hpp"
#include "tests/integration/h5_read.hpp"
#include "tests/fluid/program_scenes.hpp"
#include "tests/integration/standalone_run.hpp"
#include "tests/integration/xdmf_check.hpp"

namespace cosim::testing {
namespace {

namespace fs = std::filesystem;

class FluidFields : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = scratch_dir("fluid_fields");
    write_file(dir_ / "channel.yaml", channel_scene());
    exit_code_ = run_standalone("cosim-fluid", dir_ / "channel.yaml", dir_ / "fields.h5");
  }
  static fs::path h5() { return dir_ / "fields.h5"; }
  static inline fs::path dir_;
  static inline int exit_code_ = -1;
};

TEST_F(FluidFields, StepGroupsHoldTheFieldsWithTheirTimes) {
  ASSERT_EQ(exit_code_, 0);
  const Array x = read_array(h5(), "/fields/fluid/grid/x");
  ASSERT_EQ(x.dims, std::vector<std::size_t>{17});
  EXPECT_DOUBLE_EQ(x.values.front(), 0.0);
  EXPECT_DOUBLE_EQ(x.values.back(), 0.4);
  EXPECT_DOUBLE_EQ(x.values[8], 0.2);
  EXPECT_LT(x.values[1] - x.values[0], 0.5 * (x.values[9] - x.values[8]));  // the stretched nodes
  EXPECT_EQ(read_array(h5(), "/fields/fluid/grid/y").dims, std::vector<std::size_t>{9});
  EXPECT_EQ(read_array(h5(), "/fields/fluid/grid/z").dims, std::vector<std::size_t>{2});
  const char* const steps[] = {"000000", "000001", "000002"};
  for (int s = 0; s < 3; ++s) {
    const std::string group = std::string("/fields/fluid/") + steps[s];
    EXPECT_NEAR(read_double_attribute(h5(), group, "time"), 0.05 * s, 1e-12) << group;
    EXPECT_EQ(read_array(h5(), group + "/velocity").dims, (std::vector<std::size_t>{1, 8, 16, 3})) << group;
    EXPECT_EQ(read_array(h5(), group + "/pressure").dims, (std::vector<std::size_t>{1, 8, 16})) << group;
    EXPECT_EQ(read_array(h5(), group + "/alpha").dims, (std::vector<std::size_t>{1, 8, 16})) << group;
  }
}

TEST_F(FluidFields, AlphaMarksTheBodyAndTheFlowUpstreamIsTheInflow) {
  ASSERT_EQ(exit_code_, 0);
  const Array alpha = read_array(h5(), "/fields/fluid/000002/alpha");
  const auto cell = [](int i, int j) { return static_cast<std::size_t>(16 * j + i); };
  // The cylinder's volume fraction (r = 0.03 on cells about 0.025 wide: the cells at its
  // axis are partly outside), adding up to its section to within the level-set formula's
  // error on so coarse a grid.
  EXPECT_GT(alpha.values[cell(8, 4)], 0.4);
  EXPECT_EQ(alpha.values[cell(0, 0)], 0.0);
  EXPECT_EQ(alpha.values[cell(15, 7)], 0.0);
  const Array x = read_array(h5(), "/fields/fluid/grid/x");
  double section = 0;
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 16; ++i) section += alpha.values[cell(i, j)] * (x.values[i + 1] - x.values[i]) * 0.025;
  EXPECT_NEAR(section, 3.14159265 * 0.03 * 0.03, 0.1 * 3.14159265 * 0.03 * 0.03);
  const Array u = read_array(h5(), "/fields/fluid/000002/velocity");
  for (int j = 0; j < 8; ++j) {
    EXPECT_NEAR(u.values[3 * cell(0, j)], 0.1, 0.01) << j;
    EXPECT_NEAR(u.values[3 * cell(0, j) + 2], 0.0, 1e-12) << j;
  }
  // The fluid inside the fixed body is held back by the markers around it: at 2.4 cells per
  // diameter their kernels overlap across the body, and the axis cell keeps 28 % of the
  // inflow after two windows (held at 0.035).
  EXPECT_LT(std::abs(u.values[3 * cell(8, 4)]), 0.035);
}

TEST_F(FluidFields, XdmfSidecarNamesTheDatasetsWithTheirShapes) {
  ASSERT_EQ(exit_code_, 0);
  const XdmfContents xdmf = read_xdmf(read_file(dir_ / "fields.xmf"));
  EXPECT_EQ(xdmf.times, (std::vector<double>{0.0, 0.05, 0.1}));
  // Per step: x, y, z, velocity, pressure, alpha, and the cylinder's surface points.
  ASSERT_EQ(xdmf.items.size(), 3u * 7u);
  for (const XdmfDataItem& item : xdmf.items) {
    EXPECT_EQ(item.file, "fields.h5");
    EXPECT_EQ(read_array(dir_ / item.file, item.dataset).dims, item.dims) << item.dataset;
  }
}

// The body shows with the flow: its section's points about a cell apart on the cylinder
// (r = 0.03, cells 0.025 wide: 2 pi r / h = 7.5 of them), in the layer's midplane.
TEST_F(FluidFields, TheBodysSurfaceIsAPointSetNamedAfterIt) {
  ASSERT_EQ(exit_code_, 0);
  const Array points = read_array(h5(), "/fields/fluid/000002/points/cyl");
  ASSERT_EQ(points.dims.size(), 2u);
  EXPECT_EQ(points.dims[1], 3u);
  EXPECT_GE(points.dims[0], 6u);
  EXPECT_LE(points.dims[0], 12u);
  for (std::size_t i = 0; i < points.dims[0]; ++i) {
    EXPECT_NEAR(std::hypot(points.values[3 * i] - 0.2, points.values[3 * i + 1] - 0.1), 0.03, 1e-9) << i;
    EXPECT_DOUBLE_EQ(points.values[3 * i + 2], 0.005) << i;
  }
}

}  // namespace
}  // namespace cosim::testing
