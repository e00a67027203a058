#include "rigidbody/broadphase/levels.hpp"

#include <algorithm>
#include <cmath>

namespace cosim::rigidbody::broadphase {

Levels::Levels(double factor, double safety, double margin) : factor_(factor), safety_(safety), margin_(margin) {}

void Levels::reset(double base) {
  size_.assign(1, base);
  inv_size_.assign(1, 1.0 / base);
}

void Levels::grow_to(std::uint32_t level) {
  while (size_.size() <= level) {
    size_.push_back(size_.back() * factor_);
    inv_size_.push_back(1.0 / size_.back());
  }
}

std::uint32_t Levels::level_of(double span) {
  if (span <= size_[0]) return 0;
  // The logarithm is only a guess (it rounds); the table decides. A difference of logs
  // cannot overflow the way span / size_[0] could.
  const double guess = std::ceil((std::log(span) - std::log(size_[0])) / std::log(factor_));
  auto level = static_cast<std::uint32_t>(std::max(guess, 1.0));
  grow_to(level);
  while (size_[level] < span) grow_to(++level);
  while (level > 0 && size_[level - 1] >= span) --level;
  return level;
}

std::size_t Levels::memory_bytes() const { return (size_.capacity() + inv_size_.capacity()) * sizeof(double); }

}  // namespace cosim::rigidbody::broadphase
