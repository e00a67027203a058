#include "rigidbody/solver/impulse_cache.hpp"

namespace cosim::solver {

std::size_t ContactKeyHash::operator()(const ContactKey& k) const noexcept {
  // splitmix-style mixing: body indices are small and dense, so plain xor would collide.
  std::uint64_t h = (std::uint64_t{k.a} << 32) ^ k.b;
  h ^= std::uint64_t{k.feature} * 0x9E3779B97F4A7C15ull;
  h = (h ^ (h >> 30)) * 0xBF58476D1CE4E5B9ull;
  h = (h ^ (h >> 27)) * 0x94D049BB133111EBull;
  return static_cast<std::size_t>(h ^ (h >> 31));
}

const CachedContact* ContactImpulses::find(const ContactKey& key) const {
  const auto it = entries_.find(key);
  return it == entries_.end() ? nullptr : &it->second;
}

}  // namespace cosim::solver
