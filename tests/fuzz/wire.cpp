// fuzz_wire: the wire decoder. A frame set is refused with ProtocolError or decodes to a
// message that encodes back to the same frames; anything else is a finding.
#include <cstdlib>
#include <cstring>

#include "coupler/protocol/message.hpp"
#include "tests/fuzz/frames.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace cosim::protocol;
  const auto frames = cosim::fuzz::split_frames({reinterpret_cast<const std::byte*>(data), size});
  Message m;
  try {
    m = decode(std::span<const std::span<const std::byte>>(frames));
  } catch (const ProtocolError&) {
    return 0;
  }
  const auto encoded = encode(m);
  if (encoded.size() != frames.size()) std::abort();
  for (std::size_t i = 0; i < frames.size(); ++i)
    if (encoded[i].size() != frames[i].size() ||
        (!frames[i].empty() && std::memcmp(encoded[i].data(), frames[i].data(), frames[i].size()) != 0))
      std::abort();
  return 0;
}
