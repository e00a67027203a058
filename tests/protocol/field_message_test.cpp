// Grid fields through a Field message and back, and the frames the coupler refuses.
#include <gtest/gtest.h>

#include "protocol/field_message.hpp"

namespace cosim::protocol {
namespace {

// 2 x 3 x 1 cells on a stretched x axis, a vector and a scalar.
output::FieldFrame sample_frame() {
  output::FieldFrame f;
  f.grid.nodes = {std::vector<double>{0.0, 0.1, 0.3}, {0.0, 1.0, 2.0, 3.0}, {0.0, 0.5}};
  std::vector<double> u(18), p(6);
  for (std::size_t i = 0; i < u.size(); ++i) u[i] = 0.5 * static_cast<double>(i);
  for (std::size_t i = 0; i < p.size(); ++i) p[i] = -static_cast<double>(i);
  f.fields = {{"velocity", 3, u}, {"pressure", 1, p}};
  return f;
}

Message field_message(std::vector<Array> arrays) {
  Message m;
  m.header.type = Type::Field;
  m.header.participant = "fluid";
  m.arrays = std::move(arrays);
  return decode(encode(m));
}

TEST(FieldMessage, RoundTripsThroughTheWire) {
  const output::FieldFrame sent = sample_frame();
  const output::FieldFrame got = field_frame(field_message(field_arrays(sent)));
  EXPECT_EQ(got.grid.nodes, sent.grid.nodes);
  ASSERT_EQ(got.fields.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(got.fields[i].name, sent.fields[i].name);
    EXPECT_EQ(got.fields[i].components, sent.fields[i].components);
    EXPECT_EQ(got.fields[i].values, sent.fields[i].values);
  }
}

TEST(FieldMessage, NoFieldsIsAnEmptyMessage) {
  EXPECT_TRUE(field_arrays({}).empty());
  EXPECT_TRUE(field_frame(field_message({})).fields.empty());
}

TEST(FieldMessage, RefusesAFieldThatDoesNotFitTheGrid) {
  auto arrays = field_arrays(sample_frame());
  arrays.back() = Array::of(Tag::Field, 5, 1, std::vector<double>(5, 0.0));
  try {
    field_frame(field_message(arrays));
    FAIL() << "accepted 5 rows on 6 cells";
  } catch (const ProtocolError& e) {
    EXPECT_STREQ(e.what(), "Field message of 'fluid': field pressure has 5 rows, the grid has 6 cells");
  }
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

}  // namespace
}  // namespace cosim::protocol
