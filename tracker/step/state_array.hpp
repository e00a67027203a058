// A state as an array of doubles, as it crosses the wire and goes into checkpoints, written
// and read by typed calls in one order instead of by index: whole numbers go as doubles
// (exact up to 2^53), a vector as its three components, a 64-bit logical state as its two
// 32-bit halves.
#pragma once

#include <cmath>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "tracker/mesh/mesh.hpp"

namespace cosim::tracker::step {

template <class T>
concept StateNumber = std::integral<T> || std::floating_point<T>;

class StateWriter {
 public:
  template <class... T>
  void put(const T&... x) {
    (put_one(x), ...);
  }
  void put_bits(std::uint64_t bits) { put(bits >> 32, bits & 0xffffffffu); }
  std::vector<double> take() { return std::move(values_); }

 private:
  void put_one(StateNumber auto x) { values_.push_back(static_cast<double>(x)); }
  void put_one(const Vec3& v) { put(v[0], v[1], v[2]); }
  std::vector<double> values_;
};

class StateReader {
 public:
  explicit StateReader(std::span<const double> values) : values_(values) {}
  template <class... T>
  void get(T&... x) {
    (get_one(x), ...);
  }
  // std::runtime_error unless the value is one a T holds (a whole number in range for an
  // integral T): a damaged checkpoint is refused, not cast.
  template <StateNumber T>
  T get() {
    const double x = next();
    if constexpr (std::is_integral_v<T>) {
      if (!(x == std::floor(x) && x >= static_cast<double>(std::numeric_limits<T>::lowest()) &&
            x < std::ldexp(1.0, std::numeric_limits<T>::digits)))
        throw std::runtime_error("tracker state: " + std::to_string(x) + " where a whole number was expected");
    }
    return static_cast<T>(x);
  }
  std::uint64_t get_bits() {
    const auto high = get<std::uint64_t>();
    return high << 32 | get<std::uint64_t>();
  }
  // std::runtime_error naming `what` unless the next value is `value`.
  void expect(double value, const char* what) {
    if (const double found = next(); found != value)
      throw std::runtime_error(std::string("tracker state: ") + what + " " + std::to_string(found) +
                               ", the scene has " + std::to_string(value));
  }
  // std::runtime_error unless every value was read.
  void finish() const {
    if (at_ != values_.size()) throw std::runtime_error("tracker state: longer than this scene's");
  }

 private:
  double next() {
    if (at_ == values_.size()) throw std::runtime_error("tracker state: ends early (not this scene's?)");
    return values_[at_++];
  }
  template <StateNumber T>
  void get_one(T& x) {
    x = get<T>();
  }
  void get_one(Vec3& v) { get(v[0], v[1], v[2]); }

  std::span<const double> values_;
  std::size_t at_ = 0;
};

}  // namespace cosim::tracker::step
