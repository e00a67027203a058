#include "rigidbody/solver/contact_memory.hpp"

#include <algorithm>
#include <numeric>

namespace cosim::solver {

namespace {

bool before(const contact::PairContacts& x, const contact::PairContacts& y) {
  return x.a != y.a ? x.a < y.a : x.b < y.b;
}

}  // namespace

void ContactMemory::recall(const contact::ContactSet& contacts, std::vector<CachedContact>& out) const {
  out.assign(contacts.points.size(), CachedContact{});
  for (const contact::PairContacts& pair : contacts.pairs) {
    const auto it = std::lower_bound(pairs_.begin(), pairs_.end(), pair, before);
    if (it == pairs_.end() || it->a != pair.a || it->b != pair.b) continue;
    const std::span<const Entry> old{entries_.data() + it->first, it->count};
    for (std::uint32_t k = 0; k < pair.count; ++k) {
      const std::uint32_t feature = contacts.points[pair.first + k].feature;
      const auto match = std::find_if(old.begin(), old.end(), [&](const Entry& e) { return e.feature == feature; });
      if (match != old.end()) out[pair.first + k] = match->value;
    }
  }
}

void ContactMemory::remember(const contact::ContactSet& contacts, std::span<const CachedContact> memory) {
  // The world hands pairs over sorted already; sorting an index keeps any caller correct.
  order_.resize(contacts.pairs.size());
  std::iota(order_.begin(), order_.end(), 0u);
  std::sort(order_.begin(), order_.end(),
            [&](std::uint32_t i, std::uint32_t j) { return before(contacts.pairs[i], contacts.pairs[j]); });
  pairs_.clear();
  entries_.clear();
  for (const std::uint32_t i : order_) {
    const contact::PairContacts& p = contacts.pairs[i];
    pairs_.push_back({p.a, p.b, static_cast<std::uint32_t>(entries_.size()), p.count});
    for (std::uint32_t k = p.first; k < p.first + p.count; ++k) entries_.push_back({contacts.points[k].feature, memory[k]});
  }
}

void ContactMemory::clear() {
  pairs_.clear();
  entries_.clear();
}

}  // namespace cosim::solver
