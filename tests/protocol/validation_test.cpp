// Each way a message can be wrong is refused with a message that says which.
#include <cmath>
#include <limits>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "coupler/protocol/layout.hpp"
#include "tests/protocol/wire.hpp"

namespace cosim::protocol {
namespace {

namespace L = layout;
using testing::decode_error;
using testing::Frames;
using ::testing::HasSubstr;
using testing::poke;
using testing::to_bytes;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// Arrays: 0 Forces 2x6, 1 Poses 1x13, 2 Stats 1x2, 3 Text "ok", 4 State 1x3.
Message valid() {
  Message m;
  m.header.type = Type::Result;
  m.header.participant = "fluid";
  m.header.t0 = 1.0;
  m.header.t1 = 1.5;
  m.arrays.push_back(Array::of(Tag::Forces, 2, 6, std::vector<double>(12, 1.0)));
  m.arrays.push_back(Array::of(Tag::Poses, 1, 13, std::vector<double>(13, 0.5)));
  m.arrays.push_back(Array::of(Tag::Stats, 1, 2, {3.0, 0.01}));
  m.arrays.push_back(Array::text("ok"));
  m.arrays.push_back(Array::of(Tag::State, 1, 3, {1.0, 2.0, 3.0}));
  return m;
}

Frames valid_frames() { return to_bytes(encode(valid())); }

std::size_t descriptor(std::size_t index, std::size_t field) { return L::header_size(index) + field; }

void set_value(Frames& f, std::size_t array, std::size_t element, double v) {
  poke(f[1 + array], element * sizeof(double), v);
}

std::string encode_error(const Message& m) {
  try {
    encode(m);
  } catch (const ProtocolError& e) {
    return e.what();
  }
  ADD_FAILURE() << "encoded without error";
  return {};
}

TEST(Validation, ValidMessageDecodes) { EXPECT_EQ(testing::decode_bytes(valid_frames()).arrays.size(), 5u); }

TEST(Validation, NoFrames) { EXPECT_THAT(decode_error({}), HasSubstr("no header frame")); }

TEST(Validation, HeaderTooShortForMagic) {
  Frames f = valid_frames();
  f[0].resize(3);
  EXPECT_THAT(decode_error(f), HasSubstr("too short"));
}

TEST(Validation, HeaderTooShortForFixedPart) {
  Frames f = valid_frames();
  f[0].resize(L::kFixedSize - 1);
  EXPECT_THAT(decode_error(f), HasSubstr("too short"));
}

TEST(Validation, WrongMagic) {
  Frames f = valid_frames();
  poke(f[0], L::kMagic, std::uint32_t{0x46445025});
  EXPECT_THAT(decode_error(f), HasSubstr("not a cosim message"));
}

TEST(Validation, VersionOutsideThoseThisBuildSpeaks) {
  Frames f = valid_frames();
  poke(f[0], L::kVersion, std::uint16_t{kVersion + 1});
  f[0].resize(20);  // a future header may be laid out differently: the version still shows
  const std::string speaks = ", this build speaks 1 to " + std::to_string(kVersion);
  EXPECT_THAT(decode_error(f), HasSubstr("protocol version " + std::to_string(kVersion + 1) + speaks));
  poke(f[0], L::kVersion, std::uint16_t{0});
  EXPECT_THAT(decode_error(f), HasSubstr("protocol version 0" + speaks));
  Message m = valid();
  m.header.version = kVersion + 1;
  EXPECT_THAT(encode_error(m), HasSubstr("protocol version " + std::to_string(kVersion + 1) + speaks));
}

TEST(Validation, AnEarlierVersionsMessageIsReadAsItsVersion) {
  // Forces, Poses, Stats, Text and State: all of them arrays of the first version.
  Message m = valid();
  m.header.version = 1;
  const Message back = decode(encode(m));
  EXPECT_EQ(back.header.version, 1);
  ASSERT_EQ(back.arrays.size(), m.arrays.size());
  EXPECT_EQ(back.arrays[0].values, m.arrays[0].values);
  EXPECT_EQ(decode(encode(valid())).header.version, kVersion);
}

TEST(Validation, AnArrayNewerThanItsMessagesVersionIsRefused) {
  Message m = valid();
  m.arrays.push_back(Array::of(Tag::Responses, 2, kResponseWidth, std::vector<double>(2 * kResponseWidth, 0.0)));
  m.arrays.push_back(Array::of(Tag::Points, 1, 3, {0.0, 0.0, 0.0}));
  Frames f = to_bytes(encode(m));
  poke(f[0], L::kVersion, std::uint16_t{3});
  EXPECT_THAT(decode_error(f), HasSubstr("array 5 (Responses) came with protocol version 4, the message is version 3"));
  m.header.version = 1;
  EXPECT_THAT(encode_error(m), HasSubstr("array 5 (Responses) came with protocol version 4, the message is version 1"));
  m.arrays.erase(m.arrays.begin() + 5);
  EXPECT_THAT(encode_error(m), HasSubstr("array 5 (Points) came with protocol version 2, the message is version 1"));
}

TEST(Validation, UnknownType) {
  for (std::uint16_t type : {0, 14, 0xffff}) {
    Frames f = valid_frames();
    poke(f[0], L::kType, type);
    EXPECT_THAT(decode_error(f), HasSubstr("unknown message type " + std::to_string(type)));
  }
}

TEST(Validation, NameWithoutNul) {
  Frames f = valid_frames();
  for (std::size_t i = 0; i < kNameSize; ++i) poke(f[0], L::kName + i, 'a');
  EXPECT_THAT(decode_error(f), HasSubstr("not NUL-terminated"));
}

TEST(Validation, NameWithBadCharacter) {
  for (char c : {' ', '/', '\n', '\x7f', '\xc3'}) {
    Frames f = valid_frames();
    poke(f[0], L::kName + 2, c);
    EXPECT_THAT(decode_error(f), HasSubstr("may only use letters, digits")) << int(c);
  }
}

TEST(Validation, NameWithBytesAfterNul) {
  Frames f = valid_frames();
  poke(f[0], L::kName + 20, 'x');
  EXPECT_THAT(decode_error(f), HasSubstr("followed by bytes other than NUL"));
}

TEST(Validation, EmptyName) {
  Frames f = valid_frames();
  for (std::size_t i = 0; i < 5; ++i) poke(f[0], L::kName + i, '\0');
  EXPECT_THAT(decode_error(f), HasSubstr("participant name is empty"));
}

TEST(Validation, TooManyArrays) {
  Frames f = valid_frames();
  poke(f[0], L::kArrayCount, std::uint32_t{kMaxArrays + 1});
  EXPECT_THAT(decode_error(f), HasSubstr("65 arrays, at most 64"));
}

TEST(Validation, HeaderLengthDisagreesWithArrayCount) {
  Frames f = valid_frames();
  f[0].push_back(std::byte{0});
  EXPECT_THAT(decode_error(f), HasSubstr("does not fit its 5 arrays"));
  f = valid_frames();
  poke(f[0], L::kArrayCount, std::uint32_t{4});
  EXPECT_THAT(decode_error(f), HasSubstr("does not fit its 4 arrays"));
}

TEST(Validation, FrameCountDisagreesWithArrayCount) {
  Frames f = valid_frames();
  f.pop_back();
  EXPECT_THAT(decode_error(f), HasSubstr("message has 5 frames"));
  f = valid_frames();
  f.emplace_back();
  EXPECT_THAT(decode_error(f), HasSubstr("message has 7 frames"));
}

TEST(Validation, UnknownTag) {
  Frames f = valid_frames();
  poke(f[0], descriptor(4, L::kTag), std::uint16_t{99});
  EXPECT_THAT(decode_error(f), HasSubstr("unknown array tag 99"));
}

TEST(Validation, UnknownDType) {
  Frames f = valid_frames();
  poke(f[0], descriptor(0, L::kDType), std::uint16_t{3});
  EXPECT_THAT(decode_error(f), HasSubstr("array 0 has unknown dtype 3"));
}

TEST(Validation, DTypeNotTheTagsDType) {
  Frames f = valid_frames();
  poke(f[0], descriptor(3, L::kDType), static_cast<std::uint16_t>(DType::Float64));
  EXPECT_THAT(decode_error(f), HasSubstr("array 3 (Text) has dtype Float64"));
  f = valid_frames();
  poke(f[0], descriptor(4, L::kDType), static_cast<std::uint16_t>(DType::Bytes));
  EXPECT_THAT(decode_error(f), HasSubstr("array 4 (State) has dtype Bytes"));
}

TEST(Validation, ElementCountOverflow) {
  Frames f = valid_frames();
  poke(f[0], descriptor(4, L::kRows), std::uint32_t{0xffffffff});
  poke(f[0], descriptor(4, L::kCols), std::uint32_t{0xffffffff});
  EXPECT_THAT(decode_error(f), HasSubstr("larger than the limit"));
  f = valid_frames();  // 2^31 + 2^16 elements: just over the cap
  poke(f[0], descriptor(4, L::kRows), std::uint32_t{0x8001});
  poke(f[0], descriptor(4, L::kCols), std::uint32_t{0x10000});
  EXPECT_THAT(decode_error(f), HasSubstr("larger than the limit"));
}

TEST(Validation, PayloadSizeDisagreesWithShape) {
  Frames f = valid_frames();
  f[1].resize(11 * sizeof(double));
  EXPECT_THAT(decode_error(f), HasSubstr("array 0 (Forces) of 2 x 6 needs 96 bytes, its frame has 88"));
  f = valid_frames();
  f[4].push_back(std::byte{'!'});
  EXPECT_THAT(decode_error(f), HasSubstr("array 3 (Text) of 1 x 2 needs 2 bytes, its frame has 3"));
  f = valid_frames();
  f[5].push_back(std::byte{0});
  EXPECT_THAT(decode_error(f), HasSubstr("needs 24 bytes, its frame has 25"));
}

TEST(Validation, TimeSpan) {
  for (auto [t0, t1] : {std::pair{kNaN, 1.0}, {0.0, kInf}, {-kInf, 0.0}, {2.0, 1.0}}) {
    Frames f = valid_frames();
    poke(f[0], L::kT0, t0);
    poke(f[0], L::kT1, t1);
    EXPECT_THAT(decode_error(f), HasSubstr("invalid time span")) << t0 << " " << t1;
  }
}

TEST(Validation, NonFiniteForcesNameTagRowAndColumn) {
  Frames f = valid_frames();
  set_value(f, 0, 6 + 4, kNaN);
  EXPECT_THAT(decode_error(f), HasSubstr("array 0 (Forces) holds nan at row 1, column 4"));
}

TEST(Validation, NonFinitePoses) {
  Frames f = valid_frames();
  set_value(f, 1, 12, -kInf);
  EXPECT_THAT(decode_error(f), HasSubstr("array 1 (Poses) holds -inf at row 0, column 12"));
}

TEST(Validation, StatsAreOneRowOfTwo) {
  Message m;
  m.header.type = Type::Result;
  m.header.participant = "fluid";
  m.arrays.push_back(Array::of(Tag::Stats, 1, 1, {3.0}));
  EXPECT_THROW(encode(m), ProtocolError);
  m.arrays.back() = Array::of(Tag::Stats, 2, 2, {3.0, 0.1, 4.0, 0.2});
  try {
    encode(m);
    FAIL() << "no ProtocolError";
  } catch (const ProtocolError& e) {
    EXPECT_THAT(e.what(), HasSubstr("array 0 (Stats) has 2 rows, expected 1"));
  }
}

TEST(Validation, NonFiniteStats) {
  Frames f = valid_frames();
  set_value(f, 2, 1, kInf);
  EXPECT_THAT(decode_error(f), HasSubstr("array 2 (Stats) holds inf at row 0, column 1"));
}

TEST(Validation, PosesNeedThirteenColumns) {
  Frames f = valid_frames();
  poke(f[0], descriptor(1, L::kCols), std::uint32_t{12});
  poke(f[0], descriptor(1, L::kRows), std::uint32_t{1});
  f[2].resize(12 * sizeof(double));
  EXPECT_THAT(decode_error(f), HasSubstr("array 1 (Poses) has 12 columns, expected 13"));
}

TEST(Validation, ForcesNeedSixColumns) {
  Frames f = valid_frames();
  poke(f[0], descriptor(0, L::kRows), std::uint32_t{3});
  poke(f[0], descriptor(0, L::kCols), std::uint32_t{4});
  EXPECT_THAT(decode_error(f), HasSubstr("array 0 (Forces) has 4 columns, expected 6"));
}

TEST(Validation, TextIsOneRow) {
  Frames f = valid_frames();
  poke(f[0], descriptor(3, L::kRows), std::uint32_t{2});
  poke(f[0], descriptor(3, L::kCols), std::uint32_t{1});
  EXPECT_THAT(decode_error(f), HasSubstr("array 3 (Text) has 2 rows"));
}

TEST(Validation, HelloNeedsARank) {
  Frames f = valid_frames();
  poke(f[0], L::kType, static_cast<std::uint16_t>(Type::Hello));
  poke(f[0], L::kRanks, std::uint32_t{0});
  EXPECT_THAT(decode_error(f), HasSubstr("Hello from 'fluid' announces 0 ranks"));
}

// The encoder applies the same rules, so a bad message fails where it was made.
TEST(Validation, EncoderRefusesWhatDecoderWould) {
  Message m = valid();
  m.arrays[0].values[3] = kNaN;
  EXPECT_THAT(encode_error(m), HasSubstr("array 0 (Forces) holds nan at row 0, column 3"));
  m = valid();
  m.header.participant = std::string(kNameSize, 'a');
  EXPECT_THAT(encode_error(m), HasSubstr("longer than 31 characters"));
  m = valid();
  m.header.participant = "";
  EXPECT_THAT(encode_error(m), HasSubstr("participant name is empty"));
  m = valid();
  m.header.t1 = 0.0;
  EXPECT_THAT(encode_error(m), HasSubstr("invalid time span"));
  m = valid();
  m.arrays[4].values.pop_back();
  EXPECT_THAT(encode_error(m), HasSubstr("array 4 (State) of 1 x 3 holds 2 elements"));
  m = valid();
  m.arrays.resize(kMaxArrays + 1, Array::text("x"));
  EXPECT_THAT(encode_error(m), HasSubstr("at most 64"));
  m = valid();
  m.header.type = static_cast<Type>(0);
  EXPECT_THAT(encode_error(m), HasSubstr("unknown message type 0"));
}

// Response tensors are physics: a NaN in them, or rows of another width, fail at the sender.
TEST(Validation, ResponsesAreCheckedLikeForces) {
  Message m = valid();
  m.arrays.push_back(Array::of(Tag::Responses, 2, kResponseWidth, std::vector<double>(2 * kResponseWidth, 1.0)));
  EXPECT_NO_THROW(encode(m));
  m.arrays.back().values[kResponseWidth + 5] = kNaN;
  EXPECT_THAT(encode_error(m), HasSubstr("(Responses) holds nan at row 1, column 5"));
  m.arrays.back() = Array::of(Tag::Responses, 1, 72, std::vector<double>(72, 1.0));
  EXPECT_THAT(encode_error(m), HasSubstr("(Responses) has 72 columns, expected 78"));
}

TEST(Validation, ArrayOfChecksItsSize) {
  EXPECT_THROW(Array::of(Tag::Forces, 2, 6, std::vector<double>(11)), ProtocolError);
}

TEST(Validation, ParticipantNames) {
  EXPECT_NO_THROW(check_participant_name("fluid_2.rank-0"));
  EXPECT_THROW(check_participant_name(""), ProtocolError);
  EXPECT_THROW(check_participant_name("a b"), ProtocolError);
  EXPECT_THROW(check_participant_name(std::string(kNameSize, 'a')), ProtocolError);
  EXPECT_NO_THROW(check_participant_name(std::string(kNameSize - 1, 'a')));
}

}  // namespace
}  // namespace cosim::protocol
