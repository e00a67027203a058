#include "coupler/study/refinement.hpp"

#include <cmath>
#include <optional>

namespace cosim::study {
namespace {

// A positive number; nullopt for anything else.
std::optional<double> positive(const YAML::Node& value) {
  double v = 0;
  if (!value.IsScalar() || !YAML::convert<double>::decode(value, v) || !std::isfinite(v) || v <= 0) return std::nullopt;
  return v;
}

// Each level's size: its number, or for lists of numbers (cells per axis) the geometric mean
// of the entries that change from some level to another. Entries equal on every level are
// axes the levels do not refine (a two-dimensional grid's one cell layer, a channel's
// periodic directions): Celik et al.'s h = (1 / N)^(1/d) counts the refined axes only, d
// their number. Empty for anything else.
std::vector<double> sizes_of(const std::vector<YAML::Node>& values) {
  std::vector<std::vector<double>> entries;
  for (const auto& value : values) {
    if (const auto v = positive(value)) {
      entries.push_back({*v});
      continue;
    }
    if (!value.IsSequence() || value.size() == 0) return {};
    std::vector<double> list;
    for (const auto& entry : value) {
      const auto v = positive(entry);
      if (!v) return {};
      list.push_back(*v);
    }
    entries.push_back(std::move(list));
  }
  for (const auto& e : entries)
    if (e.size() != entries.front().size()) return {};
  std::vector<std::size_t> refined;
  for (std::size_t i = 0; i < entries.front().size(); ++i)
    for (const auto& e : entries)
      if (e[i] != entries.front()[i]) {
        refined.push_back(i);
        break;
      }
  if (refined.empty()) refined.push_back(0);  // nothing changes: every size is the same
  std::vector<double> sizes;
  for (const auto& e : entries) {
    double log_sum = 0;
    for (std::size_t i : refined) log_sum += std::log(e[i]);
    sizes.push_back(std::exp(log_sum / static_cast<double>(refined.size())));
  }
  return sizes;
}

}  // namespace

Ratios refinement_ratios(const Varied& key) {
  const std::vector<double> sizes = sizes_of(key.values);
  if (sizes.empty())
    return {{}, "the values of " + key.key + " are not positive numbers (or lists of them of one length)"};
  std::vector<double> growth;
  for (std::size_t k = 0; k + 1 < sizes.size(); ++k) growth.push_back(sizes[k + 1] / sizes[k]);
  bool grows = true, shrinks = true;
  for (double g : growth) {
    grows = grows && g > 1;
    shrinks = shrinks && g < 1;
  }
  if (!grows && !shrinks)
    return {{}, "the values of " + key.key + " neither all grow nor all shrink from level to level"};
  Ratios out;
  for (double g : growth) out.r.push_back(grows ? g : 1 / g);
  return out;
}

}  // namespace cosim::study
