// Room in a vector that every narrow phase clears and refills with one entry per contact
// point or pair. Its capacity stays what the largest count needed, and growth by doubling
// would leave up to half of that unused for the rest of the run: a packed bed's count
// sits just past a power of two as often as not (bench/rigidbody_granular/README.md
// "Where the memory goes"). An eighth more than asked keeps a growing count from
// reallocating at every step.
#pragma once

#include <cstddef>
#include <vector>

namespace cosim::rigidbody::contact {

template <class T>
void make_room(std::vector<T>& v, std::size_t count) {
  if (count > v.capacity()) v.reserve(count + count / 8);
}

}  // namespace cosim::rigidbody::contact
