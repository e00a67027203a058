// A frame's point sets through a Field message and back (after its cell fields, in three
// arrays however many sets), and the point sets a sender or the coupler refuses.
#include <gtest/gtest.h>

#include <cmath>

#include "protocol/field_message.hpp"
#include "wire.hpp"

namespace cosim::protocol {
namespace {

using testing::field_message;

// One cell with a pressure, a body of three markers and one entirely outside.
output::FieldFrame frame_with_bodies() {
  output::RectilinearGrid grid;
  grid.nodes = {std::vector<double>{0.0, 1.0}, {0.0, 2.0}, {0.0, 3.0}};
  return {std::move(grid),
          {{"pressure", 1, {4.5}}},
          {{"ball", {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, -1.0, 1e-300, 7.25}}, {"outside", {}}}};
}

// The ProtocolError text of what `f` throws, or a test failure if it throws nothing.
template <class F>
std::string refusal(F f) {
  try {
    f();
  } catch (const ProtocolError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no ProtocolError";
  return {};
}

std::string decode_refusal(std::vector<Array> arrays) {
  return refusal([&] { field_frame(field_message(std::move(arrays))); });
}

void expect_same_point_sets(const output::FieldFrame& got, const output::FieldFrame& sent) {
  ASSERT_EQ(got.point_sets.size(), sent.point_sets.size());
  for (std::size_t i = 0; i < sent.point_sets.size(); ++i) {
    EXPECT_EQ(got.point_sets[i].name, sent.point_sets[i].name);
    EXPECT_EQ(got.point_sets[i].points, sent.point_sets[i].points);
  }
}

TEST(PointSets, TwoSetsRoundTripThroughTheWire) {
  const output::FieldFrame sent = frame_with_bodies();
  const std::vector<Array> arrays = field_arrays(sent);
  ASSERT_EQ(arrays.size(), 6u + 2u + 3u);  // x, y, z, pressure, then names, counts, points
  EXPECT_EQ(arrays[8].bytes, std::string("ball\0outside\0", 13));
  EXPECT_EQ(arrays[9].values, (std::vector<double>{3, 0}));
  EXPECT_EQ(arrays[10].tag, Tag::Points);
  EXPECT_EQ(arrays[10].rows, 3u);

  const output::FieldFrame got = field_frame(field_message(arrays));
  ASSERT_EQ(got.fields.size(), 1u);
  EXPECT_EQ(got.fields[0].values, sent.fields[0].values);
  expect_same_point_sets(got, sent);
}

TEST(PointSets, OnAPolyhedralGridAndInAnAdvance) {
  output::PolyhedralGrid grid;  // one tetrahedron
  grid.vertices = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  grid.topology = {16, 4, 3, 0, 2, 1, 3, 0, 1, 3, 3, 1, 2, 3, 3, 2, 0, 3};
  grid.cells = 1;
  const output::FieldFrame sent{std::move(grid), {{"density", 1, {2.0}}}, {{"dust", {0.1, 0.1, 0.1}}}};

  Message advance;
  advance.header.type = Type::Advance;
  advance.header.participant = "tracker";
  advance.arrays = {Array::of(Tag::Forces, 1, kForceWidth, std::vector<double>(6, 1.0))};
  for (Array& a : field_arrays(sent)) advance.arrays.push_back(std::move(a));
  Message got = decode(encode(advance));
  std::vector<Array> fields = take_field_arrays(got.arrays);
  ASSERT_EQ(got.arrays.size(), 1u);
  const output::FieldFrame frame = field_frame(std::move(fields), "Advance");
  EXPECT_EQ(std::get<output::PolyhedralGrid>(frame.grid).cells, 1u);
  expect_same_point_sets(frame, sent);
}

TEST(PointSets, AFrameWithoutThemKeepsItsArrays) {
  output::FieldFrame frame = frame_with_bodies();
  frame.point_sets.clear();
  const std::vector<Array> arrays = field_arrays(frame);
  ASSERT_EQ(arrays.size(), 8u);
  EXPECT_EQ(arrays.back().tag, Tag::Field);
  EXPECT_TRUE(field_frame(field_message(arrays)).point_sets.empty());
}

// The sender learns of a name that cannot name an HDF5 dataset, or of one used twice,
// before anything leaves.
TEST(PointSets, ASenderCannotSendABadName) {
  for (const auto& [name, message] : {std::pair{"a/b", "point set name 'a/b' cannot name an HDF5 dataset"},
                                      std::pair{".", "point set name '.' cannot name an HDF5 dataset"},
                                      std::pair{"", "point set name '' cannot name an HDF5 dataset"},
                                      std::pair{"x\ny", "point set name 'x?y' cannot name an HDF5 dataset"}}) {
    output::FieldFrame frame = frame_with_bodies();
    frame.point_sets[1].name = name;
    EXPECT_EQ(refusal([&] { field_arrays(frame); }), std::string("Field arrays: ") + message);
  }
  output::FieldFrame twice = frame_with_bodies();
  twice.point_sets[1].name = "ball";
  EXPECT_EQ(refusal([&] { field_arrays(twice); }), "Field arrays: point set name 'ball' appears twice");
  output::FieldFrame ragged = frame_with_bodies();
  ragged.point_sets[0].points.pop_back();
  EXPECT_EQ(refusal([&] { field_arrays(ragged); }),
            "Field arrays: point set 'ball' has 8 coordinates, not x y z triples");
}

TEST(PointSets, TheReceiverRefusesSetsThatDoNotAddUp) {
  const std::vector<Array> good = field_arrays(frame_with_bodies());
  std::vector<Array> a = good;
  a[9].values = {2, 0};
  EXPECT_EQ(decode_refusal(a), "Field message of 'fluid': the point counts add up to 2 points, 3 were sent");
  a = good;
  a[9].values = {4, 0};
  EXPECT_EQ(decode_refusal(a), "Field message of 'fluid': point set 'ball' counts 4.000000 points, 3 are left");
  for (const double bad : {1.5, -1.0, std::nan("")}) {
    a = good;
    a[9].values[0] = bad;
    EXPECT_NE(decode_refusal(a).find("point set 'ball' counts"), std::string::npos) << bad;
  }
  a = good;
  a[9] = Array::of(Tag::Field, 1, 1, {3});
  EXPECT_EQ(decode_refusal(a), "Field message of 'fluid': 2 point set names for 1 point counts");
  a = good;
  a[8] = Array::text("ball\0outside");
  EXPECT_EQ(decode_refusal(a), "Field message of 'fluid': the point set names do not end with a NUL");
  a = good;
  a[8] = Array::text(std::string("ball\0ball\0", 10));
  EXPECT_EQ(decode_refusal(a), "Field message of 'fluid': point set name 'ball' appears twice");
  a = good;
  a.erase(a.begin() + 8);  // the names
  EXPECT_EQ(decode_refusal(a),
            "Field message of 'fluid': the points (n x 3) must follow the point sets' names (Text) and counts (1 x k)");
  a = {good.begin() + 8, good.end()};
  EXPECT_EQ(decode_refusal(a), "Field message of 'fluid': point sets without a grid and cell fields");
}

}  // namespace
}  // namespace cosim::protocol
