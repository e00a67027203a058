#include "rigidbody/solver/contact_memory.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "rigidbody/contact/room.hpp"

namespace cosim::rigidbody::solver {

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
  // Sorted pairs let recall() search; the world's pairs come sorted by construction, so
  // this only checks instead of sorting every substep.
  if (!std::is_sorted(contacts.pairs.begin(), contacts.pairs.end(), before))
    throw std::invalid_argument("contact memory: pairs must be sorted by (a, b)");
  pairs_ = contacts.pairs;
  entries_.clear();
  contact::make_room(entries_, contacts.points.size());
  for (std::size_t k = 0; k < contacts.points.size(); ++k) entries_.push_back({contacts.points[k].feature, memory[k]});
}

void ContactMemory::save(std::vector<double>& out) const {
  out.push_back(static_cast<double>(pairs_.size()));
  out.push_back(static_cast<double>(entries_.size()));
  for (const contact::PairContacts& p : pairs_) out.insert(out.end(), {double(p.a), double(p.b), double(p.count)});
  for (const Entry& e : entries_)
    out.insert(out.end(), {double(e.feature), e.value.normal, e.value.tangential.x(), e.value.tangential.y(),
                           e.value.tangential.z()});
}

void ContactMemory::load(std::span<const double> in) {
  const auto fail = [](const std::string& problem) { throw std::invalid_argument("saved contact memory: " + problem); };
  const auto index = [&](double v) {
    if (!(v >= 0.0 && v <= 4294967295.0 && v == std::floor(v))) fail("bad count or index " + std::to_string(v));
    return static_cast<std::uint32_t>(v);
  };
  if (in.size() < 2) fail("missing its two counts");
  const std::size_t pairs = index(in[0]);
  const std::size_t points = index(in[1]);
  if (in.size() != 2 + 3 * pairs + 5 * points)
    fail(std::to_string(in.size()) + " values for " + std::to_string(pairs) + " pairs and " + std::to_string(points) +
         " points");
  std::vector<contact::PairContacts> loaded_pairs;
  std::uint32_t first = 0;
  for (std::size_t i = 0; i < pairs; ++i) {
    const double* p = in.data() + 2 + 3 * i;
    loaded_pairs.push_back({index(p[0]), index(p[1]), first, index(p[2])});
    first += loaded_pairs.back().count;
  }
  if (first != points) fail("pair counts add up to " + std::to_string(first) + ", not " + std::to_string(points));
  std::vector<Entry> loaded_entries;
  for (std::size_t k = 0; k < points; ++k) {
    const double* e = in.data() + 2 + 3 * pairs + 5 * k;
    loaded_entries.push_back({index(e[0]), {.normal = e[1], .tangential = {e[2], e[3], e[4]}}});
  }
  pairs_ = std::move(loaded_pairs);
  entries_ = std::move(loaded_entries);
}

void ContactMemory::clear() {
  pairs_.clear();
  entries_.clear();
}

}  // namespace cosim::rigidbody::solver
