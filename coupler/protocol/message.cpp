#include "coupler/protocol/message.hpp"

#include <algorithm>
#include <cstdint>

#include "coupler/protocol/rules.hpp"

namespace cosim::protocol {
namespace {

bool name_char(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '.' || c == '-';
}

}  // namespace

Array Array::of(Tag tag, std::uint32_t rows, std::uint32_t cols, std::vector<double> values) {
  if (values.size() != std::uint64_t{rows} * cols)
    throw ProtocolError(std::string(to_string(tag)) + " array of " + std::to_string(rows) + " x " +
                        std::to_string(cols) + " given " + std::to_string(values.size()) + " values");
  return Array{.tag = tag, .rows = rows, .cols = cols, .values = std::move(values), .bytes = {}};
}

Array Array::text(std::string_view s) {
  if (s.size() > UINT32_MAX)
    throw ProtocolError("text of " + std::to_string(s.size()) + " bytes does not fit one array");
  return Array{
      .tag = Tag::Text, .rows = 1, .cols = static_cast<std::uint32_t>(s.size()), .values = {}, .bytes = std::string(s)};
}

const Array* Message::find(Tag tag) const {
  const auto it = std::ranges::find(arrays, tag, &Array::tag);
  return it == arrays.end() ? nullptr : &*it;
}

const Array& Message::get(Tag tag) const {
  if (const Array* a = find(tag)) return *a;
  throw ProtocolError(std::string(to_string(header.type)) + " message of '" + header.participant + "' has no " +
                      to_string(tag) + " array");
}

std::vector<const Array*> Message::all(Tag tag) const {
  std::vector<const Array*> out;
  for (const Array& a : arrays)
    if (a.tag == tag) out.push_back(&a);
  return out;
}

void check_participant_name(std::string_view name) {
  if (name.empty()) throw ProtocolError("participant name is empty");
  if (name.size() >= kNameSize)
    throw ProtocolError("participant name '" + rules::printable(name) + "' is longer than " +
                        std::to_string(kNameSize - 1) + " characters");
  if (!std::ranges::all_of(name, name_char))
    throw ProtocolError("participant name '" + rules::printable(name) +
                        "' may only use letters, digits, '_', '.' and '-'");
}

const char* to_string(Type type) {
  switch (type) {
    case Type::Hello:
      return "Hello";
    case Type::Init:
      return "Init";
    case Type::Ready:
      return "Ready";
    case Type::Advance:
      return "Advance";
    case Type::Result:
      return "Result";
    case Type::Commit:
      return "Commit";
    case Type::Checkpoint:
      return "Checkpoint";
    case Type::State:
      return "State";
    case Type::Field:
      return "Field";
    case Type::Stop:
      return "Stop";
    case Type::Abort:
      return "Abort";
    case Type::Error:
      return "Error";
    case Type::Bye:
      return "Bye";
  }
  return "unknown type";
}

const char* to_string(Tag tag) {
  switch (tag) {
    case Tag::Poses:
      return "Poses";
    case Tag::Forces:
      return "Forces";
    case Tag::Stats:
      return "Stats";
    case Tag::State:
      return "State";
    case Tag::Text:
      return "Text";
    case Tag::Field:
      return "Field";
    case Tag::Points:
      return "Points";
    case Tag::PointAttributes:
      return "PointAttributes";
    case Tag::Responses:
      return "Responses";
  }
  return "unknown tag";
}

}  // namespace cosim::protocol
