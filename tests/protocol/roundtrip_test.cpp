// Every message type survives encode/decode bit for bit, text included.
#include <bit>
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "tests/protocol/wire.hpp"

namespace cosim::protocol {
namespace {

using testing::decode_bytes;
using testing::to_bytes;

std::vector<double> ramp(std::size_t n, double start) {
  std::vector<double> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = start + 0.1 * static_cast<double>(i);
  return v;
}

Message sample(Type type) {
  Message m;
  m.header = Header{.type = type,
                    .participant = "fluid-2.a_b",
                    .window = 0x1234567890abcdefULL,
                    .iteration = 7,
                    .t0 = 0.25,
                    .t1 = 0.5,
                    .provides = 0b101,
                    .needs = 0b010,
                    .ranks = 4};
  m.arrays.push_back(Array::of(Tag::Poses, 2, 13, ramp(26, -1.0)));
  m.arrays.push_back(Array::of(Tag::Forces, 2, 6, ramp(12, 3.0)));
  m.arrays.push_back(Array::of(Tag::Responses, 2, kResponseWidth, ramp(2 * kResponseWidth, -7.0)));
  m.arrays.push_back(Array::of(Tag::Stats, 1, 2, {12.0, 0.003}));
  // Opaque arrays are not checked: NaN payloads, infinities and -0 must pass unchanged.
  m.arrays.push_back(Array::of(Tag::State, 1, 5,
                               {std::bit_cast<double>(0x7ff8dead0000beefULL), std::numeric_limits<double>::infinity(),
                                -0.0, std::numeric_limits<double>::denorm_min(), 1e300}));
  m.arrays.push_back(Array::text(std::string("name: \"ball\"\n\0binary\xff", 22)));
  m.arrays.push_back(Array::of(Tag::Field, 3, 4, ramp(12, 100.0)));
  m.arrays.push_back(Array::of(Tag::Field, 0, 4, {}));
  m.arrays.push_back(Array::text(""));
  return m;
}

void expect_same(const Message& a, const Message& b) {
  EXPECT_EQ(a.header.type, b.header.type);
  EXPECT_EQ(a.header.participant, b.header.participant);
  EXPECT_EQ(a.header.window, b.header.window);
  EXPECT_EQ(a.header.iteration, b.header.iteration);
  EXPECT_EQ(std::bit_cast<std::uint64_t>(a.header.t0), std::bit_cast<std::uint64_t>(b.header.t0));
  EXPECT_EQ(std::bit_cast<std::uint64_t>(a.header.t1), std::bit_cast<std::uint64_t>(b.header.t1));
  EXPECT_EQ(a.header.provides, b.header.provides);
  EXPECT_EQ(a.header.needs, b.header.needs);
  EXPECT_EQ(a.header.ranks, b.header.ranks);
  ASSERT_EQ(a.arrays.size(), b.arrays.size());
  for (std::size_t i = 0; i < a.arrays.size(); ++i) {
    SCOPED_TRACE("array " + std::to_string(i));
    const Array& x = a.arrays[i];
    const Array& y = b.arrays[i];
    EXPECT_EQ(x.tag, y.tag);
    EXPECT_EQ(x.rows, y.rows);
    EXPECT_EQ(x.cols, y.cols);
    EXPECT_EQ(x.bytes, y.bytes);
    ASSERT_EQ(x.values.size(), y.values.size());
    for (std::size_t k = 0; k < x.values.size(); ++k)
      EXPECT_EQ(std::bit_cast<std::uint64_t>(x.values[k]), std::bit_cast<std::uint64_t>(y.values[k]));
  }
}

class RoundTrip : public ::testing::TestWithParam<Type> {};

TEST_P(RoundTrip, DecodeGivesBackWhatWasEncoded) {
  const Message m = sample(GetParam());
  const auto frames = encode(m);
  ASSERT_EQ(frames.size(), 1 + m.arrays.size());
  expect_same(m, decode(frames));
}

TEST_P(RoundTrip, EncodingIsStable) {
  const auto bytes = to_bytes(encode(sample(GetParam())));
  EXPECT_EQ(bytes, to_bytes(encode(decode_bytes(bytes))));
}

INSTANTIATE_TEST_SUITE_P(EveryType, RoundTrip,
                         ::testing::Values(Type::Hello, Type::Init, Type::Ready, Type::Advance, Type::Result,
                                           Type::Commit, Type::Checkpoint, Type::State, Type::Field, Type::Stop,
                                           Type::Abort, Type::Error, Type::Bye),
                         [](const auto& info) { return std::string(to_string(info.param)); });

// ZeroMQ hands small frames over at any offset inside its receive buffer.
TEST(RoundTrip, PayloadAtAnyAlignment) {
  const Message m = sample(Type::Result);
  const auto frames = to_bytes(encode(m));
  for (std::size_t shift = 0; shift < sizeof(double); ++shift) {
    SCOPED_TRACE("shift " + std::to_string(shift));
    std::vector<testing::Frame> shifted;
    std::vector<std::span<const std::byte>> spans;
    shifted.reserve(frames.size());
    for (const auto& f : frames) {
      shifted.emplace_back(shift);
      shifted.back().insert(shifted.back().end(), f.begin(), f.end());
      spans.emplace_back(std::span<const std::byte>(shifted.back()).subspan(shift));
    }
    expect_same(m, decode(std::span<const std::span<const std::byte>>(spans)));
  }
}

TEST(RoundTrip, MessageWithoutArraysIsOneFrame) {
  Message m;
  m.header.type = Type::Commit;
  m.header.participant = "rigid";
  const auto frames = encode(m);
  ASSERT_EQ(frames.size(), 1u);
  expect_same(m, decode(frames));
}

TEST(RoundTrip, LargestArrayCount) {
  Message m;
  m.header.type = Type::Field;
  m.header.participant = std::string(kNameSize - 1, 'x');
  for (std::size_t i = 0; i < kMaxArrays; ++i) m.arrays.push_back(Array::text(std::to_string(i)));
  expect_same(m, decode(encode(m)));
}

TEST(Message, FindGetAndAll) {
  const Message m = sample(Type::Result);
  EXPECT_EQ(m.find(Tag::Forces)->cols, 6u);
  EXPECT_EQ(m.get(Tag::Field).rows, 3u);  // the first Field array
  const auto fields = m.all(Tag::Field);
  ASSERT_EQ(fields.size(), 2u);
  EXPECT_EQ(fields[0]->rows, 3u);
  EXPECT_EQ(fields[1]->rows, 0u);
  EXPECT_TRUE(m.all(Tag::Text).size() == 2 && m.all(Tag::Text)[1]->bytes.empty());
  Message bare;
  bare.header.type = Type::Result;
  bare.header.participant = "fluid";
  EXPECT_EQ(bare.find(Tag::Forces), nullptr);
  EXPECT_TRUE(bare.all(Tag::Forces).empty());
  try {
    bare.get(Tag::Forces);
    FAIL();
  } catch (const ProtocolError& e) {
    EXPECT_STREQ(e.what(), "Result message of 'fluid' has no Forces array");
  }
}

}  // namespace
}  // namespace cosim::protocol
