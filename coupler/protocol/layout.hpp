// Byte offsets of the header frame. Fields are copied one by one at these offsets, so the
// wire format never depends on how a compiler pads a struct.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "coupler/protocol/message.hpp"

namespace cosim::protocol::layout {

static_assert(std::endian::native == std::endian::little,
              "the wire format is little-endian and is copied without byte swapping");

inline constexpr std::size_t kMagic = 0;                   // u32
inline constexpr std::size_t kVersion = 4;                 // u16
inline constexpr std::size_t kType = 6;                    // u16
inline constexpr std::size_t kName = 8;                    // char[kNameSize]
inline constexpr std::size_t kWindow = kName + kNameSize;  // u64
inline constexpr std::size_t kIteration = kWindow + 8;     // u32
inline constexpr std::size_t kProvides = kIteration + 4;   // u32
inline constexpr std::size_t kNeeds = kProvides + 4;       // u32
inline constexpr std::size_t kRanks = kNeeds + 4;          // u32
inline constexpr std::size_t kT0 = kRanks + 4;             // f64
inline constexpr std::size_t kT1 = kT0 + 8;                // f64
inline constexpr std::size_t kArrayCount = kT1 + 8;        // u32
inline constexpr std::size_t kFixedSize = kArrayCount + 4;
static_assert(kFixedSize == 84);

// Followed by one descriptor per array.
inline constexpr std::size_t kTag = 0;    // u16
inline constexpr std::size_t kDType = 2;  // u16
inline constexpr std::size_t kRows = 4;   // u32
inline constexpr std::size_t kCols = 8;   // u32
inline constexpr std::size_t kDescriptorSize = 12;

constexpr std::size_t header_size(std::size_t n_arrays) { return kFixedSize + n_arrays * kDescriptorSize; }

template <class T>
void put(std::byte* frame, std::size_t offset, T value) {
  std::memcpy(frame + offset, &value, sizeof value);
}

template <class T>
T get(const std::byte* frame, std::size_t offset) {
  T value;
  std::memcpy(&value, frame + offset, sizeof value);
  return value;
}

}  // namespace cosim::protocol::layout
