#include "coupler/study/refinement.hpp"

#include <cmath>
#include <optional>

namespace cosim::study {
namespace {

// A number, or the geometric mean of a list of positive numbers; nullopt for anything else.
std::optional<double> size_of(const YAML::Node& value) {
  double v = 0;
  if (value.IsScalar()) {
    if (!YAML::convert<double>::decode(value, v) || !std::isfinite(v) || v <= 0) return std::nullopt;
    return v;
  }
  if (!value.IsSequence() || value.size() == 0) return std::nullopt;
  double log_sum = 0;
  for (const auto& entry : value) {
    const auto s = size_of(entry);
    if (!s || !entry.IsScalar()) return std::nullopt;
    log_sum += std::log(*s);
  }
  return std::exp(log_sum / static_cast<double>(value.size()));
}

}  // namespace

Ratios refinement_ratios(const Varied& key) {
  std::vector<double> sizes;
  for (const auto& value : key.values) {
    const auto s = size_of(value);
    if (!s) return {{}, "the values of " + key.key + " are not positive numbers (or lists of them)"};
    sizes.push_back(*s);
  }
  std::vector<double> growth;
  for (std::size_t k = 0; k + 1 < sizes.size(); ++k) growth.push_back(sizes[k + 1] / sizes[k]);
  bool grows = true, shrinks = true;
  for (double g : growth) {
    grows = grows && g > 1;
    shrinks = shrinks && g < 1;
  }
  if (!grows && !shrinks) return {{}, "the values of " + key.key + " neither all grow nor all shrink from level to level"};
  Ratios out;
  for (double g : growth) out.r.push_back(grows ? g : 1 / g);
  return out;
}

}  // namespace cosim::study
