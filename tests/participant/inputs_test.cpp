// An Advance as the coupler sends it, through the wire, into a solver's Inputs: the poses
// and forces at the window's start and end, and a forwarded field frame after them.
#include <gtest/gtest.h>

#include "coupler/participant/run_participant.hpp"
#include "coupler/protocol/field_message.hpp"

namespace cosim::participant {
namespace {

using protocol::Array;
using protocol::Tag;

// 2 x 1 x 1 cells, the fluid's velocity and pressure.
field::FieldFrame fluid_frame() {
  field::RectilinearGrid grid;
  grid.nodes = {std::vector<double>{0.0, 0.5, 1.0}, {0.0, 1.0}, {0.0, 0.1}};
  return {std::move(grid), {{"velocity", 3, {0.1, 0, 0, 0.2, 0, 0}}, {"pressure", 1, {3, 4}}}};
}

protocol::Message advance(bool with_fields) {
  protocol::Message m;
  m.header.type = protocol::Type::Advance;
  m.header.participant = "tracker";
  m.header.window = 3;
  m.header.iteration = 1;
  m.header.t0 = 0.3;
  m.header.t1 = 0.4;
  std::vector<double> start(protocol::kPoseWidth, 0.0), end(protocol::kPoseWidth, 0.0);
  start[3] = end[3] = 1.0;
  end[0] = 0.5;
  m.arrays = {Array::of(Tag::Poses, 1, protocol::kPoseWidth, start),
              Array::of(Tag::Poses, 1, protocol::kPoseWidth, end)};
  if (with_fields)
    for (Array& a : protocol::field_arrays(fluid_frame())) m.arrays.push_back(std::move(a));
  return protocol::decode(protocol::encode(m));
}

TEST(ParticipantInputs, AnAdvanceWithFieldsGivesThePosesAndTheFrame) {
  const Inputs in = inputs_of(advance(true));
  ASSERT_EQ(in.poses_start.size(), 1u);
  EXPECT_EQ(in.poses_end.at(0).position.x(), 0.5);
  EXPECT_TRUE(in.forces_start.empty());
  ASSERT_TRUE(in.fields.has_value());
  const field::FieldFrame sent = fluid_frame();
  EXPECT_EQ(std::get<field::RectilinearGrid>(in.fields->grid).nodes, std::get<field::RectilinearGrid>(sent.grid).nodes);
  ASSERT_EQ(in.fields->fields.size(), 2u);
  EXPECT_EQ(in.fields->fields[0].name, "velocity");
  EXPECT_EQ(in.fields->fields[0].components, 3);
  EXPECT_EQ(in.fields->fields[0].values, sent.fields[0].values);
  EXPECT_EQ(in.fields->fields[1].values, sent.fields[1].values);
}

TEST(ParticipantInputs, AnAdvanceWithoutFieldsGivesNone) {
  const Inputs in = inputs_of(advance(false));
  EXPECT_EQ(in.poses_end.size(), 1u);
  EXPECT_FALSE(in.fields.has_value());
}

TEST(ParticipantInputs, FieldsThatAreNoFrameAreRefused) {
  protocol::Message m = advance(true);
  m.arrays.pop_back();  // pressure's name without its values
  try {
    inputs_of(std::move(m));
    FAIL() << "took a broken frame";
  } catch (const protocol::ProtocolError& e) {
    EXPECT_NE(std::string(e.what()).find("the fields in Advance"), std::string::npos) << e.what();
  }
}

// Guards against: rows of the wrong width taken as bodies. The decoder refuses them on
// the wire; a message built in the process reaches inputs_of() unchecked.
TEST(ParticipantInputs, RowsOfTheWrongWidthAreRefused) {
  protocol::Message m = advance(false);
  m.arrays.push_back(Array::of(Tag::Forces, 1, 5, std::vector<double>(5, 0.0)));
  try {
    inputs_of(std::move(m));
    FAIL() << "took forces of 5 columns";
  } catch (const protocol::ProtocolError& e) {
    EXPECT_STREQ(e.what(), "Advance carries a Forces array of 5 columns, expected 6");
  }
}

}  // namespace
}  // namespace cosim::participant
