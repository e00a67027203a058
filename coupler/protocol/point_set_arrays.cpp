#include "coupler/protocol/point_set_arrays.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iterator>

#include "coupler/protocol/rules.hpp"

namespace cosim::protocol {
namespace {

// `what`: "point set" or "point attribute", for the message.
std::vector<std::string> split_names(const std::string& text, const std::string& who, const std::string& what) {
  std::vector<std::string> names;
  if (text.empty()) return names;
  if (text.back() != '\0') throw ProtocolError(who + ": the " + what + " names do not end with a NUL");
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t end = text.find('\0', at);
    names.push_back(text.substr(at, end - at));
    at = end + 1;
  }
  return names;
}

bool whole(double x, double lo, double hi) { return x >= lo && x <= hi && x == std::floor(x); }  // NaN fails

std::vector<double> slice(const std::vector<double>& values, std::size_t at, std::size_t end) {
  return {values.begin() + static_cast<std::ptrdiff_t>(at), values.begin() + static_cast<std::ptrdiff_t>(end)};
}

void push_attributes(std::vector<Array>& arrays, const std::vector<field::PointSet>& sets) {
  std::string names;
  std::vector<double> set, components, integer, values;
  for (std::size_t i = 0; i < sets.size(); ++i)
    for (const field::PointAttribute& a : sets[i].attributes) {
      names += a.name;
      names += '\0';
      set.push_back(static_cast<double>(i));
      components.push_back(a.components);
      integer.push_back(a.integer ? 1.0 : 0.0);
      values.insert(values.end(), a.values.begin(), a.values.end());
    }
  if (set.empty()) return;
  const auto a = static_cast<std::uint32_t>(set.size());
  const auto m = static_cast<std::uint32_t>(values.size());  // before the values move out
  set.insert(set.end(), components.begin(), components.end());
  set.insert(set.end(), integer.begin(), integer.end());
  arrays.push_back(Array::text(names));
  arrays.push_back(Array::of(Tag::Field, 3, a, std::move(set)));
  arrays.push_back(Array::of(Tag::PointAttributes, 1, m, std::move(values)));
}

// The three attribute arrays moved off the end of `arrays`, or none if the last is not theirs.
std::vector<Array> take_attribute_arrays(std::vector<Array>& arrays, const std::string& who) {
  if (arrays.empty() || arrays.back().tag != Tag::PointAttributes) return {};
  const std::size_t n = arrays.size();
  if (n < 3 || arrays[n - 3].tag != Tag::Text || arrays[n - 2].tag != Tag::Field || arrays[n - 2].rows != 3 ||
      arrays[n - 1].rows != 1)
    throw ProtocolError(who + ": the point attribute values (1 x m) must follow their names (Text) and shapes (3 x a)");
  std::vector<Array> out(std::make_move_iterator(arrays.end() - 3), std::make_move_iterator(arrays.end()));
  arrays.resize(n - 3);
  return out;
}

// Gives each set the attributes the three arrays (names, shapes, values) describe.
void add_attributes(std::vector<field::PointSet>& sets, const std::vector<Array>& a, const std::string& who) {
  if (a.empty()) return;
  const std::vector<std::string> names = split_names(a[0].bytes, who, "point attribute");
  const std::vector<double>& shape = a[1].values;
  const std::vector<double>& values = a[2].values;
  const std::size_t n = names.size();
  if (a[1].cols != n)
    throw ProtocolError(who + ": " + std::to_string(n) + " point attribute names for " + std::to_string(a[1].cols) +
                        " shapes");
  std::size_t at = 0;  // in values
  double previous = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::string attribute = "point attribute '" + rules::printable(names[i]) + "'";
    const double set = shape[i], components = shape[n + i], integer = shape[2 * n + i];
    // Sets in order: a message has one way to say a frame.
    if (!whole(set, previous, static_cast<double>(sets.size()) - 1))
      throw ProtocolError(who + ": " + attribute + " names set " + std::to_string(set) + " after set " +
                          std::to_string(previous) + ", of " + std::to_string(sets.size()) + " sets");
    if (!whole(components, 1, INT_MAX))
      throw ProtocolError(who + ": " + attribute + " has " + std::to_string(components) + " components");
    if (integer != 0.0 && integer != 1.0)
      throw ProtocolError(who + ": " + attribute + " is marked integer " + std::to_string(integer) + ", not 0 or 1");
    field::PointSet& s = sets[static_cast<std::size_t>(set)];
    const std::size_t points = s.points.size() / 3, left = values.size() - at;
    // Divided, not multiplied: no product can overflow.
    if (points > 0 && left / points < static_cast<std::size_t>(components))
      throw ProtocolError(who + ": " + attribute + " of point set '" + rules::printable(s.name) + "' takes " +
                          std::to_string(points) + " x " + std::to_string(components) + " values, " +
                          std::to_string(left) + " are left");
    const std::size_t end = at + points * static_cast<std::size_t>(components);
    s.attributes.push_back({names[i], static_cast<int>(components), slice(values, at, end), integer == 1.0});
    at = end;
    previous = set;
  }
  if (at != values.size())
    throw ProtocolError(who + ": the point attributes take " + std::to_string(at) + " values, " +
                        std::to_string(values.size()) + " were sent");
}

}  // namespace

void push_point_sets(std::vector<Array>& arrays, const std::vector<field::PointSet>& sets) {
  if (sets.empty()) return;
  std::string names;
  std::vector<double> counts, points;
  for (const field::PointSet& s : sets) {
    names += s.name;
    names += '\0';
    counts.push_back(static_cast<double>(s.points.size() / 3));
    points.insert(points.end(), s.points.begin(), s.points.end());
  }
  const auto k = static_cast<std::uint32_t>(counts.size());
  const auto n = static_cast<std::uint32_t>(points.size() / 3);  // before the values move out
  arrays.push_back(Array::text(names));
  arrays.push_back(Array::of(Tag::Field, 1, k, std::move(counts)));
  arrays.push_back(Array::of(Tag::Points, n, 3, std::move(points)));
  push_attributes(arrays, sets);
}

std::vector<field::PointSet> take_point_sets(std::vector<Array>& arrays, const std::string& who) {
  const std::vector<Array> attributes = take_attribute_arrays(arrays, who);
  if (arrays.empty() || arrays.back().tag != Tag::Points) {
    if (!attributes.empty()) throw ProtocolError(who + ": point attributes without the point sets (n x 3) before them");
    return {};
  }
  const std::size_t first = arrays.size() < 3 ? 0 : arrays.size() - 3;
  if (arrays.size() < 3 || arrays[first].tag != Tag::Text || arrays[first + 1].tag != Tag::Field ||
      arrays[first + 1].rows != 1)
    throw ProtocolError(who + ": the points (n x 3) must follow the point sets' names (Text) and counts (1 x k)");
  const std::vector<std::string> names = split_names(arrays[first].bytes, who, "point set");
  const std::vector<double>& counts = arrays[first + 1].values;
  const std::vector<double>& points = arrays[first + 2].values;
  if (names.size() != counts.size())
    throw ProtocolError(who + ": " + std::to_string(names.size()) + " point set names for " +
                        std::to_string(counts.size()) + " point counts");
  std::vector<field::PointSet> sets;
  std::size_t at = 0;  // in points, 3 per point
  for (std::size_t i = 0; i < names.size(); ++i) {
    const double n = counts[i];
    // At most what is left: no sum can overflow, and a NaN fails too.
    if (!whole(n, 0.0, static_cast<double>((points.size() - at) / 3)))
      throw ProtocolError(who + ": point set '" + rules::printable(names[i]) + "' counts " + std::to_string(n) +
                          " points, " + std::to_string((points.size() - at) / 3) + " are left");
    const std::size_t end = at + 3 * static_cast<std::size_t>(n);
    sets.push_back({names[i], slice(points, at, end)});
    at = end;
  }
  if (at != points.size())
    throw ProtocolError(who + ": the point counts add up to " + std::to_string(at / 3) + " points, " +
                        std::to_string(points.size() / 3) + " were sent");
  add_attributes(sets, attributes, who);
  if (const std::string problem = field::point_sets_problem(sets); !problem.empty())
    throw ProtocolError(who + ": " + problem);
  arrays.resize(first);
  return sets;
}

}  // namespace cosim::protocol
