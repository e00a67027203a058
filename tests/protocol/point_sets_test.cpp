// A frame's point sets through a Field message and back (after its cell fields, in three
// arrays however many sets, and three more for their attributes), and the point sets a
// sender or the coupler refuses.
#include <gtest/gtest.h>

#include <cmath>

#include "coupler/protocol/field_message.hpp"
#include "tests/protocol/wire.hpp"

namespace cosim::protocol {
namespace {

using testing::field_message;

// One cell with a pressure, a body of three markers and one entirely outside.
field::FieldFrame frame_with_bodies() {
  field::RectilinearGrid grid;
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

void expect_same_point_sets(const field::FieldFrame& got, const field::FieldFrame& sent) {
  ASSERT_EQ(got.point_sets.size(), sent.point_sets.size());
  for (std::size_t i = 0; i < sent.point_sets.size(); ++i) {
    const field::PointSet &g = got.point_sets[i], &s = sent.point_sets[i];
    EXPECT_EQ(g.name, s.name);
    EXPECT_EQ(g.points, s.points);
    ASSERT_EQ(g.attributes.size(), s.attributes.size()) << s.name;
    for (std::size_t k = 0; k < s.attributes.size(); ++k) {
      EXPECT_EQ(g.attributes[k].name, s.attributes[k].name);
      EXPECT_EQ(g.attributes[k].components, s.attributes[k].components);
      EXPECT_EQ(g.attributes[k].values, s.attributes[k].values);
      EXPECT_EQ(g.attributes[k].integer, s.attributes[k].integer);
    }
  }
}

// The bodies' frame with attributes: two on the ball, none on the body outside, one on a
// third set of one point.
field::FieldFrame frame_with_attributes() {
  field::FieldFrame frame = frame_with_bodies();
  frame.point_sets[0].attributes = {{"velocity", 3, {1, 2, 3, 4, 5, 6, 7, 8, 9.5}},
                                    {"state", 2, {4294967295.0, 0, 1, 2, 0x1p53, -7}, true}};
  frame.point_sets.push_back({"dust", {1, 1, 1}, {{"cell", 1, {12}, true}}});
  return frame;
}

TEST(PointSets, TwoSetsRoundTripThroughTheWire) {
  const field::FieldFrame sent = frame_with_bodies();
  const std::vector<Array> arrays = field_arrays(sent);
  ASSERT_EQ(arrays.size(), 6u + 2u + 3u);  // x, y, z, pressure, then names, counts, points
  EXPECT_EQ(arrays[8].bytes, std::string("ball\0outside\0", 13));
  EXPECT_EQ(arrays[9].values, (std::vector<double>{3, 0}));
  EXPECT_EQ(arrays[10].tag, Tag::Points);
  EXPECT_EQ(arrays[10].rows, 3u);

  const field::FieldFrame got = field_frame(field_message(arrays));
  ASSERT_EQ(got.fields.size(), 1u);
  EXPECT_EQ(got.fields[0].values, sent.fields[0].values);
  expect_same_point_sets(got, sent);
}

TEST(PointSets, OnAPolyhedralGridAndInAnAdvance) {
  field::PolyhedralGrid grid;  // one tetrahedron
  grid.vertices = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  grid.topology = {16, 4, 3, 0, 2, 1, 3, 0, 1, 3, 3, 1, 2, 3, 3, 2, 0, 3};
  grid.cells = 1;
  const field::FieldFrame sent{std::move(grid), {{"density", 1, {2.0}}}, {{"dust", {0.1, 0.1, 0.1}}}};

  Message advance;
  advance.header.type = Type::Advance;
  advance.header.participant = "tracker";
  advance.arrays = {Array::of(Tag::Forces, 1, kForceWidth, std::vector<double>(6, 1.0))};
  for (Array& a : field_arrays(sent)) advance.arrays.push_back(std::move(a));
  Message got = decode(encode(advance));
  std::vector<Array> fields = take_field_arrays(got.arrays);
  ASSERT_EQ(got.arrays.size(), 1u);
  const field::FieldFrame frame = field_frame(std::move(fields), "Advance");
  EXPECT_EQ(std::get<field::PolyhedralGrid>(frame.grid).cells, 1u);
  expect_same_point_sets(frame, sent);
}

TEST(PointSets, AttributesRoundTripThroughTheWire) {
  const field::FieldFrame sent = frame_with_attributes();
  const std::vector<Array> arrays = field_arrays(sent);
  ASSERT_EQ(arrays.size(), 6u + 2u + 3u + 3u);  // ..., names, shapes, values of the attributes
  EXPECT_EQ(arrays[10].tag, Tag::Points);
  EXPECT_EQ(arrays[11].bytes, std::string("velocity\0state\0cell\0", 20));
  EXPECT_EQ(arrays[12].rows, 3u);
  EXPECT_EQ(arrays[12].values, (std::vector<double>{0, 0, 2, 3, 2, 1, 0, 1, 1}));  // sets, components, integer
  EXPECT_EQ(arrays[13].tag, Tag::PointAttributes);
  EXPECT_EQ(arrays[13].values.size(), 9u + 6u + 1u);
  expect_same_point_sets(field_frame(field_message(arrays)), sent);
}

// The tracker's particles when none are left (or none is in the sample): no values at all.
TEST(PointSets, AnEmptySetKeepsItsAttributes) {
  field::FieldFrame sent = frame_with_bodies();
  sent.point_sets = {{"particles", {}, {{"velocity", 3, {}}, {"cell", 1, {}, true}}}};
  const std::vector<Array> arrays = field_arrays(sent);
  ASSERT_EQ(arrays.back().tag, Tag::PointAttributes);
  EXPECT_TRUE(arrays.back().values.empty());
  expect_same_point_sets(field_frame(field_message(arrays)), sent);
}

TEST(PointSets, TheReceiverRefusesAttributesThatDoNotAddUp) {
  const std::vector<Array> good = field_arrays(frame_with_attributes());
  const auto with_shape = [&](std::size_t at, double value) {
    std::vector<Array> a = good;
    a[12].values[at] = value;
    return decode_refusal(a);
  };
  const std::string who = "Field message of 'fluid': ";
  EXPECT_EQ(with_shape(2, 1), who + "the point attributes take 15 values, 16 were sent");  // cell on the body outside
  EXPECT_EQ(with_shape(1, 3), who + "point attribute 'state' names set 3.000000 after set 0.000000, of 3 sets");
  EXPECT_EQ(with_shape(0, 1), who + "point attribute 'state' names set 0.000000 after set 1.000000, of 3 sets");
  EXPECT_EQ(with_shape(4, 3),
            who + "point attribute 'state' of point set 'ball' takes 3 x 3.000000 values, 7 are left");
  for (const double bad : {0.0, 1.5, std::nan("")})
    EXPECT_NE(with_shape(3, bad).find(who + "point attribute 'velocity' has"), std::string::npos) << bad;
  EXPECT_EQ(with_shape(6, 2), who + "point attribute 'velocity' is marked integer 2.000000, not 0 or 1");
  // A float attribute may hold any value, an integer one only whole numbers.
  EXPECT_EQ(with_shape(6, 1),
            who + "attribute 'velocity' of point set 'ball' holds 9.500000, not a whole number within +-2^53");
  std::vector<Array> a = good;
  a[13].values.push_back(1);
  a[13].cols += 1;
  EXPECT_EQ(decode_refusal(a), who + "the point attributes take 16 values, 17 were sent");
  a = good;
  a[11] = Array::text(std::string("velocity\0state\0", 15));
  EXPECT_EQ(decode_refusal(a), who + "2 point attribute names for 3 shapes");
  a = good;
  a[11] = Array::text(std::string("velocity\0velocity\0cell\0", 23));
  EXPECT_EQ(decode_refusal(a), who + "attribute name 'velocity' appears twice in point set 'ball'");
  a = good;
  a[11] = Array::text("velocity");
  EXPECT_EQ(decode_refusal(a), who + "the point attribute names do not end with a NUL");
  a = good;
  a.erase(a.begin() + 12);  // the shapes
  EXPECT_EQ(decode_refusal(a),
            who + "the point attribute values (1 x m) must follow their names (Text) and shapes (3 x a)");
  a = good;
  a.erase(a.begin() + 8, a.begin() + 11);  // the sets
  EXPECT_EQ(decode_refusal(a), who + "point attributes without the point sets (n x 3) before them");
}

// The sender learns of an attribute that does not fit its set before anything leaves.
TEST(PointSets, ASenderCannotSendABadAttribute) {
  field::FieldFrame frame = frame_with_attributes();
  frame.point_sets[2].attributes[0].values = {12, 13};
  EXPECT_EQ(refusal([&] { field_arrays(frame); }),
            "Field arrays: attribute 'cell' of point set 'dust' has 2 values for 1 points of 1 components");
}

TEST(PointSets, AFrameWithoutThemKeepsItsArrays) {
  field::FieldFrame frame = frame_with_bodies();
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
    field::FieldFrame frame = frame_with_bodies();
    frame.point_sets[1].name = name;
    EXPECT_EQ(refusal([&] { field_arrays(frame); }), std::string("Field arrays: ") + message);
  }
  field::FieldFrame twice = frame_with_bodies();
  twice.point_sets[1].name = "ball";
  EXPECT_EQ(refusal([&] { field_arrays(twice); }), "Field arrays: point set name 'ball' appears twice");
  field::FieldFrame ragged = frame_with_bodies();
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
