#include "protocol/point_set_arrays.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>

#include "protocol/rules.hpp"

namespace cosim::protocol {
namespace {

std::vector<std::string> split_names(const std::string& text, const std::string& who) {
  std::vector<std::string> names;
  if (text.empty()) return names;
  if (text.back() != '\0') throw ProtocolError(who + ": the point set names do not end with a NUL");
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t end = text.find('\0', at);
    names.push_back(text.substr(at, end - at));
    at = end + 1;
  }
  return names;
}

}  // namespace

void push_point_sets(std::vector<Array>& arrays, const std::vector<output::PointSet>& sets) {
  if (sets.empty()) return;
  std::string names;
  std::vector<double> counts, points;
  for (const output::PointSet& s : sets) {
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
}

std::vector<output::PointSet> take_point_sets(std::vector<Array>& arrays, const std::string& who) {
  if (arrays.empty() || arrays.back().tag != Tag::Points) return {};
  const std::size_t first = arrays.size() < 3 ? 0 : arrays.size() - 3;
  if (arrays.size() < 3 || arrays[first].tag != Tag::Text || arrays[first + 1].tag != Tag::Field ||
      arrays[first + 1].rows != 1)
    throw ProtocolError(who + ": the points (n x 3) must follow the point sets' names (Text) and counts (1 x k)");
  const std::vector<std::string> names = split_names(arrays[first].bytes, who);
  const std::vector<double>& counts = arrays[first + 1].values;
  const std::vector<double>& points = arrays[first + 2].values;
  if (names.size() != counts.size())
    throw ProtocolError(who + ": " + std::to_string(names.size()) + " point set names for " +
                        std::to_string(counts.size()) + " point counts");
  std::vector<output::PointSet> sets;
  std::size_t at = 0;  // in points, 3 per point
  for (std::size_t i = 0; i < names.size(); ++i) {
    const double n = counts[i];
    // At most what is left: no sum can overflow, and a NaN fails too.
    if (!(n >= 0.0 && n <= static_cast<double>((points.size() - at) / 3) && n == std::floor(n)))
      throw ProtocolError(who + ": point set '" + rules::printable(names[i]) + "' counts " + std::to_string(n) +
                          " points, " + std::to_string((points.size() - at) / 3) + " are left");
    const std::size_t end = at + 3 * static_cast<std::size_t>(n);
    sets.push_back({names[i], std::vector<double>(points.begin() + static_cast<std::ptrdiff_t>(at),
                                                  points.begin() + static_cast<std::ptrdiff_t>(end))});
    at = end;
  }
  if (at != points.size())
    throw ProtocolError(who + ": the point counts add up to " + std::to_string(at / 3) + " points, " +
                        std::to_string(points.size() / 3) + " were sent");
  if (const std::string problem = output::point_sets_problem(sets); !problem.empty())
    throw ProtocolError(who + ": " + problem);
  arrays.resize(first);
  return sets;
}

}  // namespace cosim::protocol
