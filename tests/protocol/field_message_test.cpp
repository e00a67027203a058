// Grid fields through a Field message and back, and the frames the coupler refuses.
#include <gtest/gtest.h>

#include <cmath>

#include "coupler/protocol/field_message.hpp"
#include "tests/protocol/wire.hpp"

namespace cosim::protocol {
namespace {

using testing::field_message;

// 2 x 3 x 1 cells on a stretched x axis, a vector and a scalar.
field::FieldFrame sample_frame() {
  field::RectilinearGrid grid;
  grid.nodes = {std::vector<double>{0.0, 0.1, 0.3}, {0.0, 1.0, 2.0, 3.0}, {0.0, 0.5}};
  std::vector<double> u(18), p(6);
  for (std::size_t i = 0; i < u.size(); ++i) u[i] = 0.5 * static_cast<double>(i);
  for (std::size_t i = 0; i < p.size(); ++i) p[i] = -static_cast<double>(i);
  return {std::move(grid), {{"velocity", 3, u}, {"pressure", 1, p}}};
}

// Two tetrahedra on the faces of a triangular bipyramid (vertices 0, 1, 2 the shared face,
// 3 above, 4 below), a vector and a scalar.
field::FieldFrame polyhedral_frame() {
  field::PolyhedralGrid grid;
  grid.vertices = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0.3, 0.3, 1, 0.3, 0.3, -1};
  grid.topology = {16, 4, 3, 0, 2, 1, 3, 0, 1, 3, 3, 1, 2, 3, 3, 2, 0, 3,
                   16, 4, 3, 0, 1, 2, 3, 0, 4, 1, 3, 1, 4, 2, 3, 2, 4, 0};
  grid.cells = 2;
  return {std::move(grid), {{"velocity", 3, {1, 2, 3, 4, 5, 6}}, {"density", 1, {1e20, 2.5e19}}}};
}

// The ProtocolError text of decoding arrays, or a test failure if they make a frame.
std::string refusal(std::vector<Array> arrays) {
  try {
    field_frame(field_message(std::move(arrays)));
  } catch (const ProtocolError& e) {
    return e.what();
  }
  ADD_FAILURE() << "decoded without error";
  return {};
}

void expect_same_fields(const field::FieldFrame& got, const field::FieldFrame& sent) {
  ASSERT_EQ(got.fields.size(), sent.fields.size());
  for (std::size_t i = 0; i < sent.fields.size(); ++i) {
    EXPECT_EQ(got.fields[i].name, sent.fields[i].name);
    EXPECT_EQ(got.fields[i].components, sent.fields[i].components);
    EXPECT_EQ(got.fields[i].values, sent.fields[i].values);
  }
}

TEST(FieldMessage, RoundTripsThroughTheWire) {
  const field::FieldFrame sent = sample_frame();
  const field::FieldFrame got = field_frame(field_message(field_arrays(sent)));
  ASSERT_TRUE(std::holds_alternative<field::RectilinearGrid>(got.grid));
  EXPECT_EQ(std::get<field::RectilinearGrid>(got.grid).nodes, std::get<field::RectilinearGrid>(sent.grid).nodes);
  expect_same_fields(got, sent);
}

TEST(FieldMessage, RoundTripsAPolyhedralGrid) {
  field::FieldFrame sent = polyhedral_frame();
  const auto arrays = field_arrays(sent);
  ASSERT_EQ(arrays.size(), 8u);  // vertices, topology, two fields
  const field::FieldFrame got = field_frame(field_message(arrays));
  ASSERT_TRUE(std::holds_alternative<field::PolyhedralGrid>(got.grid));
  const auto& grid = std::get<field::PolyhedralGrid>(got.grid);
  const auto& expected = std::get<field::PolyhedralGrid>(sent.grid);
  EXPECT_EQ(grid.vertices, expected.vertices);
  EXPECT_EQ(grid.topology, expected.topology);
  EXPECT_EQ(grid.cells, 2u);
  expect_same_fields(got, sent);
}

TEST(FieldMessage, NoFieldsIsAnEmptyMessage) {
  EXPECT_TRUE(field_arrays({}).empty());
  EXPECT_TRUE(field_frame(field_message({})).fields.empty());
}

TEST(FieldMessage, RefusesAFieldThatDoesNotFitTheGrid) {
  auto arrays = field_arrays(sample_frame());
  arrays.back() = Array::of(Tag::Field, 5, 1, std::vector<double>(5, 0.0));
  EXPECT_EQ(refusal(arrays), "Field message of 'fluid': field pressure has 5 rows, the grid has 6 cells");
}

TEST(FieldMessage, RefusesAMissingAxis) {
  auto arrays = field_arrays(sample_frame());
  arrays.erase(arrays.begin() + 2, arrays.begin() + 4);  // y
  EXPECT_THROW(field_frame(field_message(arrays)), ProtocolError);
  arrays = field_arrays(sample_frame());
  arrays[0] = Array::text("z");
  EXPECT_THROW(field_frame(field_message(arrays)), ProtocolError);
}

TEST(FieldMessage, RefusesANameWithoutValues) {
  auto arrays = field_arrays(sample_frame());
  arrays.pop_back();
  EXPECT_THROW(field_frame(field_message(arrays)), ProtocolError);
}

// The topology travels as float64: anything but a whole number in range is not one.
TEST(FieldMessage, RefusesATopologyEntryThatIsNotAnInteger) {
  for (const double bad : {1.5, -1.0, 9007199254740992.0, std::nan("")}) {
    auto arrays = field_arrays(polyhedral_frame());
    arrays[3].values[4] = bad;
    EXPECT_NE(refusal(arrays).find("topology entry"), std::string::npos) << bad;
  }
}

TEST(FieldMessage, RefusesATopologyThatIsNotTheFieldsCells) {
  auto arrays = field_arrays(polyhedral_frame());
  for (std::size_t i : {5u, 7u})
    arrays[i] = Array::of(Tag::Field, 1, arrays[i].cols, std::vector<double>(arrays[i].cols));
  EXPECT_EQ(refusal(arrays), "Field message of 'fluid': the topology holds 2 cells, the grid says 1");

  arrays = field_arrays(polyhedral_frame());
  arrays[3].values[5] = 5;  // a vertex index past the 5 vertices
  EXPECT_EQ(refusal(arrays), "Field message of 'fluid': cell 0 of the topology names vertex 5 of 5");

  arrays = field_arrays(polyhedral_frame());
  arrays[3].values.resize(20);
  arrays[3].cols = 20;
  EXPECT_EQ(refusal(arrays), "Field message of 'fluid': the topology ends inside cell 1");
}

TEST(FieldMessage, RefusesVerticesWithoutTheTopology) {
  auto arrays = field_arrays(polyhedral_frame());
  arrays.erase(arrays.begin() + 2, arrays.begin() + 4);
  EXPECT_EQ(refusal(arrays),
            "Field message of 'fluid': vertices (v x 3) must be followed by the topology (1 x n) and a field");
}

TEST(FieldMessage, ASenderCannotSendABrokenGrid) {
  field::FieldFrame frame = polyhedral_frame();
  std::get<field::PolyhedralGrid>(frame.grid).topology[0] = 12;  // a hexahedron's code, not a polyhedron's
  EXPECT_THROW(field_arrays(frame), ProtocolError);
}

// The coupler forwards a frame after an Advance's inputs; the participant splits it off.
TEST(FieldMessage, AnAdvanceCarriesTheFieldsAfterItsInputs) {
  Message m;
  m.header.type = Type::Advance;
  m.header.participant = "tracker";
  const std::vector<double> pose{0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  m.arrays = {Array::of(Tag::Poses, 1, kPoseWidth, pose), Array::of(Tag::Poses, 1, kPoseWidth, pose)};
  const std::vector<Array> fields = field_arrays(sample_frame());
  // Grid nodes 3 + 4 + 2, velocity 18 and pressure 6 values; the names x, y, z, velocity, pressure.
  EXPECT_EQ(payload_bytes(fields), 8 * (9 + 18 + 6) + 3 + 8 + 8);
  m.arrays.insert(m.arrays.end(), fields.begin(), fields.end());

  Message got = decode(encode(m));
  std::vector<Array> taken = take_field_arrays(got.arrays);
  ASSERT_EQ(got.arrays.size(), 2u);
  EXPECT_EQ(got.arrays[1].values, pose);
  const field::FieldFrame frame = field_frame(std::move(taken), "Advance");
  EXPECT_EQ(std::get<field::RectilinearGrid>(frame.grid).nodes,
            std::get<field::RectilinearGrid>(sample_frame().grid).nodes);
  expect_same_fields(frame, sample_frame());

  Message inputs_only = decode(encode(Message{m.header, {m.arrays[0]}}));
  EXPECT_TRUE(take_field_arrays(inputs_only.arrays).empty());
  EXPECT_EQ(inputs_only.arrays.size(), 1u);
}

}  // namespace
}  // namespace cosim::protocol
