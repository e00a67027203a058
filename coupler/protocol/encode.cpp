#include <cstring>

#include "coupler/protocol/layout.hpp"
#include "coupler/protocol/rules.hpp"

namespace cosim::protocol {
namespace {

namespace L = layout;

// The bytes of array `index` as they go on the wire, once its shape and values are valid.
std::span<const std::byte> payload(std::size_t index, const Array& a, std::uint16_t version) {
  rules::check_shape(index, a.tag, a.rows, a.cols, version);
  const bool text = rules::dtype_of(a.tag) == DType::Bytes;
  const std::uint64_t held = text ? a.bytes.size() : a.values.size();
  if (held != std::uint64_t{a.rows} * a.cols)
    throw ProtocolError("array " + std::to_string(index) + " (" + to_string(a.tag) + ") of " + std::to_string(a.rows) +
                        " x " + std::to_string(a.cols) + " holds " + std::to_string(held) + " elements");
  if (text) return std::as_bytes(std::span(a.bytes));
  rules::check_values(index, a.tag, a.cols, a.values);
  return std::as_bytes(std::span(a.values));
}

zmq::message_t header_frame(const Header& h, std::span<const Array> arrays) {
  zmq::message_t frame(L::header_size(arrays.size()));
  auto* p = static_cast<std::byte*>(frame.data());
  std::memset(p, 0, frame.size());  // the NUL padding of the name
  L::put(p, L::kMagic, kMagic);
  L::put(p, L::kVersion, h.version);
  L::put(p, L::kType, static_cast<std::uint16_t>(h.type));
  std::memcpy(p + L::kName, h.participant.data(), h.participant.size());
  L::put(p, L::kWindow, h.window);
  L::put(p, L::kIteration, h.iteration);
  L::put(p, L::kProvides, h.provides);
  L::put(p, L::kNeeds, h.needs);
  L::put(p, L::kRanks, h.ranks);
  L::put(p, L::kT0, h.t0);
  L::put(p, L::kT1, h.t1);
  L::put(p, L::kArrayCount, static_cast<std::uint32_t>(arrays.size()));
  for (std::size_t i = 0; i < arrays.size(); ++i) {
    std::byte* d = p + L::header_size(i);
    L::put(d, L::kTag, static_cast<std::uint16_t>(arrays[i].tag));
    L::put(d, L::kDType, static_cast<std::uint16_t>(rules::dtype_of(arrays[i].tag)));
    L::put(d, L::kRows, arrays[i].rows);
    L::put(d, L::kCols, arrays[i].cols);
  }
  return frame;
}

}  // namespace

std::vector<zmq::message_t> encode(const Header& header, std::span<const Array> arrays) {
  rules::check_header(header);
  if (arrays.size() > kMaxArrays)
    throw ProtocolError("message has " + std::to_string(arrays.size()) + " arrays, at most " +
                        std::to_string(kMaxArrays) + " are allowed");
  std::vector<std::span<const std::byte>> payloads;
  payloads.reserve(arrays.size());
  for (std::size_t i = 0; i < arrays.size(); ++i) payloads.push_back(payload(i, arrays[i], header.version));

  std::vector<zmq::message_t> frames;
  frames.reserve(1 + arrays.size());
  frames.push_back(header_frame(header, arrays));
  for (const auto& bytes : payloads) frames.emplace_back(bytes.data(), bytes.size());
  return frames;
}

std::vector<zmq::message_t> encode(const Message& m) { return encode(m.header, m.arrays); }

}  // namespace cosim::protocol
