// Messages as plain bytes, so tests can build, edit and decode them without sockets.
#pragma once

#include <cstddef>
#include <cstring>
#include <span>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "coupler/protocol/message.hpp"

namespace cosim::protocol::testing {

using Frame = std::vector<std::byte>;
using Frames = std::vector<Frame>;

inline Frames to_bytes(const std::vector<zmq::message_t>& frames) {
  Frames out;
  for (const auto& f : frames) {
    const auto* p = static_cast<const std::byte*>(f.data());
    out.emplace_back(p, p + f.size());
  }
  return out;
}

inline Message decode_bytes(const Frames& frames) {
  std::vector<std::span<const std::byte>> spans(frames.begin(), frames.end());
  return decode(std::span<const std::span<const std::byte>>(spans));
}

template <class T>
void poke(Frame& frame, std::size_t offset, T value) {
  std::memcpy(frame.data() + offset, &value, sizeof value);
}

// The ProtocolError text of decoding frames, or a test failure if it decodes.
inline std::string decode_error(const Frames& frames) {
  try {
    decode_bytes(frames);
  } catch (const ProtocolError& e) {
    return e.what();
  }
  ADD_FAILURE() << "decoded without error";
  return {};
}

// A Field message of participant "fluid" carrying `arrays`, encoded and decoded again.
inline Message field_message(std::vector<Array> arrays) {
  Message m;
  m.header.type = Type::Field;
  m.header.participant = "fluid";
  m.arrays = std::move(arrays);
  return decode(encode(m));
}

}  // namespace cosim::protocol::testing
