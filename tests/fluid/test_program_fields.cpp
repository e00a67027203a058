// cosim-fluid --standalone writes cell-centred fields and an XDMF sidecar naming them.
#include <gtest/gtest.h>

#include <filesystem>

#include "cosim_process.hpp"
#include "h5_read.hpp"
#include "program_scenes.hpp"
#include "standalone_run.hpp"
#include "xdmf_check.hpp"

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
  EXPECT_EQ(alpha.values[cell(8, 4)], 1.0);  // centre within 0.018 of the axis
  EXPECT_EQ(alpha.values[cell(0, 0)], 0.0);
  EXPECT_EQ(alpha.values[cell(15, 7)], 0.0);
  const Array u = read_array(h5(), "/fields/fluid/000002/velocity");
  for (int j = 0; j < 8; ++j) {
    EXPECT_NEAR(u.values[3 * cell(0, j)], 0.1, 0.01) << j;
    EXPECT_NEAR(u.values[3 * cell(0, j) + 2], 0.0, 1e-12) << j;
  }
  EXPECT_NEAR(u.values[3 * cell(8, 4)], 0.0, 1e-12);  // at rest inside the fixed body
}

TEST_F(FluidFields, XdmfSidecarNamesTheDatasetsWithTheirShapes) {
  ASSERT_EQ(exit_code_, 0);
  const XdmfContents xdmf = read_xdmf(read_file(dir_ / "fields.xmf"));
  EXPECT_EQ(xdmf.times, (std::vector<double>{0.0, 0.05, 0.1}));
  ASSERT_EQ(xdmf.items.size(), 3u * 6u);  // per step: x, y, z, velocity, pressure, alpha
  for (const XdmfDataItem& item : xdmf.items) {
    EXPECT_EQ(item.file, "fields.h5");
    EXPECT_EQ(read_array(dir_ / item.file, item.dataset).dims, item.dims) << item.dataset;
  }
}

}  // namespace
}  // namespace cosim::testing
