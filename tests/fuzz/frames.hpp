// How fuzz_wire reads one fuzzer input as the frames of a ZeroMQ multipart message: each
// frame is a little-endian u16 length and then that many bytes (fewer if the input ends
// first). wire_seeds writes its seeds the same way.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace cosim::fuzz {

inline std::vector<std::span<const std::byte>> split_frames(std::span<const std::byte> input) {
  std::vector<std::span<const std::byte>> frames;
  while (input.size() >= 2) {
    const std::size_t length = std::to_integer<std::size_t>(input[0]) | std::to_integer<std::size_t>(input[1]) << 8;
    input = input.subspan(2);
    const std::size_t taken = length < input.size() ? length : input.size();
    frames.push_back(input.first(taken));
    input = input.subspan(taken);
  }
  return frames;
}

inline void append_frame(std::string& out, std::span<const std::byte> frame) {
  out.push_back(static_cast<char>(frame.size() & 0xff));
  out.push_back(static_cast<char>(frame.size() >> 8 & 0xff));
  out.append(reinterpret_cast<const char*>(frame.data()), frame.size());
}

}  // namespace cosim::fuzz
