#include "coupler/run/warning_rate.hpp"

#include <fmt/format.h>

#include <utility>

namespace cosim::run {
namespace {

std::string repeats(long n) { return fmt::format("{} more time{}", n, n == 1 ? "" : "s"); }

}  // namespace

std::optional<std::string> WarningRate::admit(const std::string& text, clock::time_point now) {
  const auto [it, first] = seen_.try_emplace(text, Seen{now, 0});
  if (first) return text;
  Seen& s = it->second;
  if (now - s.said < period_) {
    ++s.held;
    return std::nullopt;
  }
  s.said = now;
  const long held = std::exchange(s.held, 0);
  return held > 0 ? fmt::format("{} (and {} since it was last shown)", text, repeats(held)) : text;
}

std::vector<std::string> WarningRate::held_back() {
  std::vector<std::string> out;
  for (auto& [text, s] : seen_)
    if (s.held > 0)
      out.push_back(fmt::format("{} ({} since it was last shown)", text, repeats(std::exchange(s.held, 0))));
  return out;
}

}  // namespace cosim::run
