#include <charconv>
#include <cstdint>
#include <cstring>

#include "coupler/protocol/layout.hpp"
#include "coupler/protocol/rules.hpp"

namespace cosim::protocol {
namespace {

namespace L = layout;
using Bytes = std::span<const std::byte>;

std::string hex(std::uint32_t v) {
  char digits[8];
  return "0x" + std::string(digits, std::to_chars(digits, digits + 8, v, 16).ptr);
}

// Magic and version come first so that a message from another program or another
// protocol version is named as such, whatever its length.
void check_preamble(Bytes head) {
  if (head.size() < L::kType)  // magic and version
    throw ProtocolError("header frame of " + std::to_string(head.size()) + " bytes is too short for a cosim message");
  if (const auto magic = L::get<std::uint32_t>(head.data(), L::kMagic); magic != kMagic)
    throw ProtocolError("not a cosim message (magic " + hex(magic) + ", expected " + hex(kMagic) + ")");
  if (const auto version = L::get<std::uint16_t>(head.data(), L::kVersion);
      version < kOldestVersion || version > kVersion)
    throw ProtocolError("protocol version " + std::to_string(version) + ", this build speaks " +
                        std::to_string(kOldestVersion) + " to " + std::to_string(kVersion));
  if (head.size() < L::kFixedSize)
    throw ProtocolError("header frame of " + std::to_string(head.size()) +
                        " bytes is too short, a cosim header needs " + "at least " + std::to_string(L::kFixedSize));
}

// NUL padding is required all the way so that every valid header has one encoding.
std::string read_name(const std::byte* field) {
  const auto* chars = reinterpret_cast<const char*>(field);
  const auto* end = static_cast<const char*>(std::memchr(chars, '\0', kNameSize));
  if (!end) throw ProtocolError("participant name is not NUL-terminated");
  for (const char* c = end; c != chars + kNameSize; ++c)
    if (*c != '\0') throw ProtocolError("participant name is followed by bytes other than NUL");
  return std::string(chars, end);
}

Header read_header(const std::byte* p) {
  Header h;
  h.type = static_cast<Type>(L::get<std::uint16_t>(p, L::kType));
  h.participant = read_name(p + L::kName);
  h.window = L::get<std::uint64_t>(p, L::kWindow);
  h.iteration = L::get<std::uint32_t>(p, L::kIteration);
  h.provides = L::get<std::uint32_t>(p, L::kProvides);
  h.needs = L::get<std::uint32_t>(p, L::kNeeds);
  h.ranks = L::get<std::uint32_t>(p, L::kRanks);
  h.t0 = L::get<double>(p, L::kT0);
  h.t1 = L::get<double>(p, L::kT1);
  h.version = L::get<std::uint16_t>(p, L::kVersion);
  rules::check_header(h);
  return h;
}

// Checks descriptor `index` against its payload frame; returns the array without data.
Array read_descriptor(std::size_t index, const std::byte* d, Bytes payload, std::uint16_t version) {
  const auto tag = static_cast<Tag>(L::get<std::uint16_t>(d, L::kTag));
  const auto dtype = L::get<std::uint16_t>(d, L::kDType);
  const auto rows = L::get<std::uint32_t>(d, L::kRows);
  const auto cols = L::get<std::uint32_t>(d, L::kCols);
  const std::string label = "array " + std::to_string(index);
  if (dtype != static_cast<std::uint16_t>(DType::Float64) && dtype != static_cast<std::uint16_t>(DType::Bytes))
    throw ProtocolError(label + " has unknown dtype " + std::to_string(dtype));
  rules::check_shape(index, tag, rows, cols, version);
  if (static_cast<DType>(dtype) != rules::dtype_of(tag))
    throw ProtocolError(label + " (" + to_string(tag) + ") has dtype " +
                        (dtype == static_cast<std::uint16_t>(DType::Bytes) ? "Bytes" : "Float64") +
                        ", which this tag never uses");
  const std::uint64_t width = static_cast<DType>(dtype) == DType::Bytes ? 1 : sizeof(double);
  const std::uint64_t expected = std::uint64_t{rows} * cols * width;
  if (payload.size() != expected)
    throw ProtocolError(label + " (" + to_string(tag) + ") of " + std::to_string(rows) + " x " + std::to_string(cols) +
                        " needs " + std::to_string(expected) + " bytes, its frame has " +
                        std::to_string(payload.size()));
  return Array{.tag = tag, .rows = rows, .cols = cols, .values = {}, .bytes = {}};
}

// The one copy out of the frame, bytewise: frames may sit at any offset in ZeroMQ's
// receive buffer, and reading their bytes as doubles in place would break aliasing rules.
void fill(std::size_t index, Array& a, Bytes payload) {
  if (rules::dtype_of(a.tag) == DType::Bytes) {
    a.bytes.assign(reinterpret_cast<const char*>(payload.data()), payload.size());
    return;
  }
  a.values.resize(payload.size() / sizeof(double));
  if (!payload.empty()) std::memcpy(a.values.data(), payload.data(), payload.size());
  rules::check_values(index, a.tag, a.cols, a.values);
}

}  // namespace

Message decode(std::span<const Bytes> frames) {
  if (frames.empty()) throw ProtocolError("empty message: no header frame");
  const Bytes head = frames[0];
  check_preamble(head);
  const std::byte* p = head.data();

  Message m{.header = read_header(p), .arrays = {}};
  const auto n = L::get<std::uint32_t>(p, L::kArrayCount);
  if (n > kMaxArrays)
    throw ProtocolError("header announces " + std::to_string(n) + " arrays, at most " + std::to_string(kMaxArrays) +
                        " are allowed");
  if (head.size() != L::header_size(n))
    throw ProtocolError("header frame of " + std::to_string(head.size()) + " bytes does not fit its " +
                        std::to_string(n) + " arrays (" + std::to_string(L::header_size(n)) + " bytes)");
  if (frames.size() != 1 + std::size_t{n})
    throw ProtocolError("message has " + std::to_string(frames.size()) + " frames, its header announces " +
                        std::to_string(n) + " arrays and so " + std::to_string(1 + n) + " frames");

  // Every size is checked before any payload is copied.
  m.arrays.reserve(n);
  for (std::size_t i = 0; i < n; ++i)
    m.arrays.push_back(read_descriptor(i, p + L::header_size(i), frames[1 + i], m.header.version));
  for (std::size_t i = 0; i < n; ++i) fill(i, m.arrays[i], frames[1 + i]);
  return m;
}

Message decode(std::span<const zmq::message_t> frames) {
  std::vector<Bytes> bytes;
  bytes.reserve(frames.size());
  for (const auto& f : frames) bytes.emplace_back(static_cast<const std::byte*>(f.data()), f.size());
  return decode(std::span<const Bytes>(bytes));
}

}  // namespace cosim::protocol
