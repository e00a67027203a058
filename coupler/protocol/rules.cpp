#include "coupler/protocol/rules.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>

namespace cosim::protocol::rules {
namespace {

std::string array_label(std::size_t index, Tag tag) {
  return "array " + std::to_string(index) + " (" + to_string(tag) + ")";
}

// Shortest text that reads back to the same double, where to_string would print 1e-9 as 0.
std::string number(double v) {
  char text[32];
  return std::string(text, std::to_chars(text, text + sizeof text, v).ptr);
}

bool known(Type type) {
  const auto v = static_cast<std::uint16_t>(type);
  return v >= static_cast<std::uint16_t>(Type::Hello) && v <= static_cast<std::uint16_t>(Type::Bye);
}

}  // namespace

std::string printable(std::string_view name) {
  std::string out(name);
  std::ranges::replace_if(
      out, [](char c) { return c < ' ' || c > '~'; }, '?');
  return out;
}

DType dtype_of(Tag tag) {
  switch (tag) {
    case Tag::Poses:
    case Tag::Forces:
    case Tag::Stats:
    case Tag::State:
    case Tag::Field:
    case Tag::Points:
    case Tag::PointAttributes:
    case Tag::Responses:
      return DType::Float64;
    case Tag::Text:
      return DType::Bytes;
  }
  throw ProtocolError("unknown array tag " + std::to_string(static_cast<unsigned>(tag)));
}

std::uint16_t first_version(Tag tag) {
  switch (tag) {
    case Tag::Points:
      return 2;
    case Tag::PointAttributes:
      return 3;
    case Tag::Responses:
      return 4;
    default:
      return 1;
  }
}

void check_header(const Header& h) {
  if (h.version < kOldestVersion || h.version > kVersion)
    throw ProtocolError("protocol version " + std::to_string(h.version) + ", this build speaks " +
                        std::to_string(kOldestVersion) + " to " + std::to_string(kVersion));
  if (!known(h.type)) throw ProtocolError("unknown message type " + std::to_string(static_cast<unsigned>(h.type)));
  check_participant_name(h.participant);
  if (!std::isfinite(h.t0) || !std::isfinite(h.t1) || h.t1 < h.t0)
    throw ProtocolError(std::string(to_string(h.type)) + " message of '" + h.participant +
                        "' has an invalid time span [" + number(h.t0) + ", " + number(h.t1) + "]");
  if (h.type == Type::Hello && h.ranks < 1) throw ProtocolError("Hello from '" + h.participant + "' announces 0 ranks");
}

void check_shape(std::size_t index, Tag tag, std::uint32_t rows, std::uint32_t cols, std::uint16_t version) {
  dtype_of(tag);  // rejects unknown tags
  if (first_version(tag) > version)
    throw ProtocolError(array_label(index, tag) + " came with protocol version " + std::to_string(first_version(tag)) +
                        ", the message is version " + std::to_string(version));
  const auto need_cols = [&](std::uint32_t n) {
    if (cols != n)
      throw ProtocolError(array_label(index, tag) + " has " + std::to_string(cols) + " columns, expected " +
                          std::to_string(n));
  };
  if (tag == Tag::Poses) need_cols(kPoseWidth);
  if (tag == Tag::Forces) need_cols(kForceWidth);
  if (tag == Tag::Responses) need_cols(kResponseWidth);
  if (tag == Tag::Points) need_cols(3);
  if (tag == Tag::Stats) {
    need_cols(kStatsWidth);
    if (rows != 1) throw ProtocolError(array_label(index, tag) + " has " + std::to_string(rows) + " rows, expected 1");
  }
  if (tag == Tag::Text && rows != 1)
    throw ProtocolError(array_label(index, tag) + " has " + std::to_string(rows) +
                        " rows, text is a single row of bytes");
  if (std::uint64_t{rows} * cols > kMaxElements)
    throw ProtocolError(array_label(index, tag) + " of " + std::to_string(rows) + " x " + std::to_string(cols) +
                        " elements is larger than the limit of " + std::to_string(kMaxElements));
}

void check_values(std::size_t index, Tag tag, std::uint32_t cols, std::span<const double> values) {
  if (tag != Tag::Poses && tag != Tag::Forces && tag != Tag::Responses && tag != Tag::Stats) return;
  for (std::size_t i = 0; i < values.size(); ++i)
    if (!std::isfinite(values[i]))
      throw ProtocolError(array_label(index, tag) + " holds " + number(values[i]) + " at row " +
                          std::to_string(i / cols) + ", column " + std::to_string(i % cols));
}

}  // namespace cosim::protocol::rules
