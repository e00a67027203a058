// What makes a message valid, apart from its byte layout. The encoder applies the same
// rules as the decoder, so a sender learns about a bad message before it leaves.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "coupler/protocol/message.hpp"

namespace cosim::protocol::rules {

// Far beyond any field we exchange (16 GiB of doubles), and far enough below 2^64 that no
// size computed from a descriptor can overflow.
inline constexpr std::uint64_t kMaxElements = std::uint64_t{1} << 31;

// The dtype an array with this tag must have; throws ProtocolError for an unknown tag.
DType dtype_of(Tag tag);

// Names reach error messages from untrusted bytes: keep them on one readable line.
std::string printable(std::string_view name);

// The protocol version that added arrays with this tag.
std::uint16_t first_version(Tag tag);

void check_header(const Header& header);
// Tag, shape and size of array number `index` of a message of `version`.
void check_shape(std::size_t index, Tag tag, std::uint32_t rows, std::uint32_t cols, std::uint16_t version);
// NaN/Inf where physics is expected (Poses, Forces, Stats).
void check_values(std::size_t index, Tag tag, std::uint32_t cols, std::span<const double> values);

}  // namespace cosim::protocol::rules
