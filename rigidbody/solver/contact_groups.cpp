#include "rigidbody/solver/contact_groups.hpp"

#include <numeric>

namespace cosim::rigidbody::solver {

namespace {

struct DisjointSets {
  std::vector<std::uint32_t> parent;

  explicit DisjointSets(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t root(std::uint32_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];  // path halving
    return i;
  }
  void join(std::uint32_t i, std::uint32_t j) { parent[root(i)] = root(j); }
};

}  // namespace

std::vector<std::vector<std::uint32_t>> contact_groups(std::span<const dynamics::BodyInertia> inertias,
                                                       std::span<const contact::PairContacts> pairs) {
  DisjointSets sets(inertias.size());
  for (const auto& m : pairs)
    if (!inertias[m.a].is_fixed() && !inertias[m.b].is_fixed()) sets.join(m.a, m.b);

  constexpr std::uint32_t kNone = ~0u;
  std::vector<std::uint32_t> group_of_root(inertias.size(), kNone);
  std::vector<std::vector<std::uint32_t>> groups;
  for (std::uint32_t i = 0; i < pairs.size(); ++i) {
    const auto& m = pairs[i];
    const std::uint32_t body = inertias[m.a].is_fixed() ? m.b : m.a;
    if (inertias[body].is_fixed()) continue;
    auto& g = group_of_root[sets.root(body)];
    if (g == kNone) {
      g = static_cast<std::uint32_t>(groups.size());
      groups.emplace_back();
    }
    groups[g].push_back(i);
  }
  return groups;
}

}  // namespace cosim::rigidbody::solver
