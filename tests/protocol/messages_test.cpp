// The message factories fill the header as docs/protocol.md's table says, carry their
// arrays in the documented order and pass the encoder's checks.
#include <gtest/gtest.h>

#include "coupler/protocol/messages.hpp"

namespace cosim::protocol {
namespace {

struct Expected {
  Type type;
  std::uint64_t window = 0;
  std::uint32_t iteration = 0;
  double t0 = 0, t1 = 0;
};

// m's header is `e` (the rest at the defaults), and m survives the wire unchanged.
void expect_header(Message m, const Expected& e) {
  m.header.participant = "fluid";
  const Message got = decode(encode(m));
  const Header& h = got.header;
  EXPECT_EQ(h.type, e.type);
  EXPECT_EQ(h.window, e.window) << to_string(e.type);
  EXPECT_EQ(h.iteration, e.iteration) << to_string(e.type);
  EXPECT_EQ(h.t0, e.t0) << to_string(e.type);
  EXPECT_EQ(h.t1, e.t1) << to_string(e.type);
  if (e.type != Type::Hello) {
    EXPECT_EQ(h.provides, 0u);
    EXPECT_EQ(h.needs, 0u);
    EXPECT_EQ(h.ranks, 1u);
  }
  ASSERT_EQ(got.arrays.size(), m.arrays.size()) << to_string(e.type);
  for (std::size_t i = 0; i < m.arrays.size(); ++i) {
    EXPECT_EQ(got.arrays[i].tag, m.arrays[i].tag);
    EXPECT_EQ(got.arrays[i].values, m.arrays[i].values);
    EXPECT_EQ(got.arrays[i].bytes, m.arrays[i].bytes);
  }
}

std::vector<Array> outputs() {
  return {Array::of(Tag::Forces, 1, kForceWidth, {1, 2, 3, 4, 5, 6}), Array::of(Tag::Stats, 1, kStatsWidth, {7, 0.5})};
}

TEST(Messages, TheCouplersHeadersAreThoseOfTheProtocol) {
  const Array poses = Array::of(Tag::Poses, 1, kPoseWidth, {0, 0, 1, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0});
  const Message fresh = messages::init(0, 0.0, 1.3, "scene.yaml", "time: {end: 1.3}", poses, std::nullopt);
  expect_header(fresh, {Type::Init, 0, 0, 0.0, 1.3});
  ASSERT_EQ(fresh.arrays.size(), 3u);
  EXPECT_EQ(fresh.arrays[0].bytes, "scene.yaml");
  EXPECT_EQ(fresh.arrays[1].bytes, "time: {end: 1.3}");
  EXPECT_EQ(fresh.arrays[2].tag, Tag::Poses);
  const Message resumed = messages::init(6, 0.3, 1.3, "scene.yaml", "", poses, std::vector<double>{});
  expect_header(resumed, {Type::Init, 6, 0, 0.3, 1.3});
  ASSERT_EQ(resumed.arrays.size(), 4u);
  EXPECT_EQ(resumed.arrays[3].tag, Tag::State);  // an empty state is still sent

  expect_header(messages::advance(4, 2, 0.2, 0.25, {poses, poses}), {Type::Advance, 4, 2, 0.2, 0.25});
  expect_header(messages::commit(5), {Type::Commit, 5});
  expect_header(messages::checkpoint(6), {Type::Checkpoint, 6});
  expect_header(messages::field_request(7, 0.35), {Type::Field, 7, 0, 0.35, 0.35});
  expect_header(messages::stop(), {Type::Stop});
  const Message abort = messages::abort("the fluid failed");
  expect_header(abort, {Type::Abort});
  EXPECT_EQ(abort.arrays.at(0).bytes, "the fluid failed");
}

TEST(Messages, TheParticipantsHeadersAreThoseOfTheProtocol) {
  const Message hello = messages::hello(0b101, 0b010, 4);
  expect_header(hello, {Type::Hello});
  EXPECT_EQ(hello.header.provides, 0b101u);
  EXPECT_EQ(hello.header.needs, 0b010u);
  EXPECT_EQ(hello.header.ranks, 4u);
  expect_header(messages::ready(outputs()), {Type::Ready});
  expect_header(messages::result(4, 2, outputs()), {Type::Result, 4, 2});
  const Message state = messages::state({1.5, -2});
  expect_header(state, {Type::State});
  EXPECT_EQ(state.arrays.at(0).cols, 2u);
  expect_header(messages::fields(7, {Array::text("p"), Array::of(Tag::Field, 1, 1, {3})}), {Type::Field, 7});
  const Message error = messages::error("diverged");
  expect_header(error, {Type::Error});
  EXPECT_EQ(error.arrays.at(0).bytes, "diverged");
  expect_header(messages::bye(), {Type::Bye});
}

}  // namespace
}  // namespace cosim::protocol
