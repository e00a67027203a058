// Cell fields written in blocks (a box spread over MPI ranks, received rank by rank): the
// file holds what one write of the whole frame holds, whatever the blocks' offsets along
// each axis, and the writer refuses blocks that do not fit.
#include <gtest/gtest.h>

#include <hdf5.h>

#include <functional>

#include "coupler/output/field_writer.hpp"
#include "coupler/output/h5_handle.hpp"
#include "tests/output/h5_read.hpp"
#include "tests/output/temp_dir.hpp"

namespace cosim::output::test {
namespace {

using FieldBlocksTest = TempDirTest;

constexpr std::array<std::size_t, 3> kCells{3, 4, 5};

field::RectilinearGrid grid() {
  field::RectilinearGrid g;
  for (std::size_t a = 0; a < 3; ++a)
    for (std::size_t i = 0; i <= kCells[a]; ++i) g.nodes[a].push_back(0.1 * double(i * i) + double(a));
  return g;
}

// A scalar and a vector whose values tell the cell (and the component) apart.
double value(std::size_t i, std::size_t j, std::size_t k, int c) { return double(i + 10 * j + 100 * k) + 0.25 * c; }

field::CellBlock block(std::array<std::size_t, 3> lo, std::array<std::size_t, 3> hi) {
  field::CellBlock b{lo, hi, {{"p", 1, {}}, {"u", 3, {}}}};
  for (std::size_t k = lo[2]; k < hi[2]; ++k)
    for (std::size_t j = lo[1]; j < hi[1]; ++j)
      for (std::size_t i = lo[0]; i < hi[0]; ++i) {
        b.fields[0].values.push_back(value(i, j, k, 0));
        for (int c = 0; c < 3; ++c) b.fields[1].values.push_back(value(i, j, k, c));
      }
  return b;
}

field::FieldFrame layout() { return {grid(), {{"p", 1, {}}, {"u", 3, {}}}}; }

struct File {
  explicit File(const std::filesystem::path& path)
      : handle(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose, "create") {}
  Handle handle;
};

// Guards against: a block placed with its axes swapped or its offset along one axis lost
// (each of the eight blocks has its own offsets along all three axes).
TEST_F(FieldBlocksTest, EightBricksWriteWhatTheWholeFrameWrites) {
  const auto whole_path = file("whole.h5"), blocks_path = file("blocks.h5");
  {
    File f(whole_path);
    FieldWriter writer(whole_path);
    field::FieldFrame frame = layout();
    frame.fields = block({0, 0, 0}, kCells).fields;
    writer.write(f.handle.get(), "tracker", 7, 0.5, frame);
  }
  {
    File f(blocks_path);
    FieldWriter writer(blocks_path);
    writer.write(f.handle.get(), "tracker", 7, 0.5, layout(), [](const FieldWriter::BlockSink& take) {
      const std::array<std::size_t, 3> cut{1, 3, 2};
      for (int corner = 7; corner >= 0; --corner) {  // in no particular order
        std::array<std::size_t, 3> lo{}, hi{};
        for (int a = 0; a < 3; ++a) {
          const bool high = corner >> a & 1;
          lo[a] = high ? cut[a] : 0;
          hi[a] = high ? kCells[a] : cut[a];
        }
        take(block(lo, hi));
      }
    });
  }
  ReadFile whole(whole_path), blocks(blocks_path);
  for (const char* name :
       {"/fields/tracker/000007/p", "/fields/tracker/000007/u", "/fields/tracker/grid/x", "/fields/tracker/grid/z"}) {
    EXPECT_EQ(blocks.dims(name), whole.dims(name)) << name;
    EXPECT_EQ(blocks.doubles(name), whole.doubles(name)) << name;
  }
  EXPECT_EQ(blocks.dims("/fields/tracker/000007/u"), (std::vector<hsize_t>{5, 4, 3, 3}));
}

TEST_F(FieldBlocksTest, RefusesBlocksThatDoNotFit) {
  const auto path = file("bad.h5");
  File f(path);
  FieldWriter writer(path);
  std::uint64_t window = 0;
  const auto refused = [&](const std::function<void(const FieldWriter::BlockSink&)>& blocks, const std::string& says) {
    try {
      writer.write(f.handle.get(), "tracker", window++, 0.0, layout(), blocks);
      ADD_FAILURE() << "accepted: " << says;
    } catch (const ObjectError& e) {
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    }
  };
  refused([](const auto& take) { take(block({0, 0, 0}, {3, 4, 6})); }, "along z, where the grid has 5");
  refused([](const auto& take) { take(block({0, 0, 0}, {3, 4, 4})); }, "blocks of 48 cells for a grid of 60");
  refused(
      [](const auto& take) {
        take(block({0, 0, 0}, {3, 4, 3}));
        take(block({1, 2, 2}, {3, 4, 5}));  // 12 cells again, 60 in all
      },
      "cell (1, 2, 2) in two blocks");
  refused(
      [](const auto& take) {
        field::CellBlock b = block({0, 0, 0}, kCells);
        b.fields[1].values.pop_back();
        take(b);
      },
      "field u (179 values)");
  refused(
      [](const auto& take) {
        field::CellBlock b = block({0, 0, 0}, kCells);
        b.fields.pop_back();
        take(b);
      },
      "a block of 1 fields");
  field::FieldFrame with_values = layout();
  with_values.fields[0].values = {1.0};
  try {
    writer.write(f.handle.get(), "tracker", window++, 0.0, with_values, [](const auto&) {});
    ADD_FAILURE() << "accepted a layout with values";
  } catch (const ObjectError& e) {
    EXPECT_NE(std::string(e.what()).find("values come in blocks"), std::string::npos) << e.what();
  }
}

// field::place puts blocks where the whole frame has their cells (the coupled tracker's
// frame, put together from its ranks' bricks), and refuses one that does not fit.
TEST(FieldBlocks, PlacedBlocksMakeTheWholeFields) {
  std::vector<field::CellField> whole{{"p", 1, std::vector<double>(60, -1.0)},
                                      {"u", 3, std::vector<double>(180, -1.0)}};
  for (const auto& [lo, hi] : std::vector<std::pair<std::array<std::size_t, 3>, std::array<std::size_t, 3>>>{
           {{0, 0, 0}, {2, 4, 5}}, {{2, 0, 0}, {3, 1, 5}}, {{2, 1, 0}, {3, 4, 5}}})
    field::place(block(lo, hi), kCells, whole);
  const field::CellBlock expected = block({0, 0, 0}, kCells);
  EXPECT_EQ(whole[0].values, expected.fields[0].values);
  EXPECT_EQ(whole[1].values, expected.fields[1].values);
  EXPECT_THROW(field::place(block({0, 0, 1}, {3, 4, 6}), kCells, whole), std::invalid_argument);
}

}  // namespace
}  // namespace cosim::output::test
