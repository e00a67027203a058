// A checked view of one YAML mapping. The loader reads the scene through it and every
// program reads its own `options` through it, so all errors name file, line, key and value
// the same way, and a key nobody asked for is reported instead of silently ignored.
#pragma once

#include <yaml-cpp/yaml.h>

#include <limits>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "coupler/scene/scene.hpp"

namespace cosim::scene {

// An interval a number must lie in; an open end excludes its bound. Built only through the
// named constructors so a brace list meant as a Vec3 can never turn into a Range.
class Range {
 public:
  Range() = default;                                                              // any finite number
  static Range above(double lo) { return {lo, inf, true, false}; }                // (lo, inf)
  static Range at_least(double lo) { return {lo, inf, false, false}; }            // [lo, inf)
  static Range closed(double lo, double hi) { return {lo, hi, false, false}; }    // [lo, hi]
  static Range left_open(double lo, double hi) { return {lo, hi, true, false}; }  // (lo, hi]
  static Range open(double lo, double hi) { return {lo, hi, true, true}; }        // (lo, hi)

  bool contains(double v) const;
  std::string requirement() const;  // what a value outside must hear: "must be in (0, 1]"

 private:
  static constexpr double inf = std::numeric_limits<double>::infinity();
  Range(double lo, double hi, bool open_lo, bool open_hi) : lo_(lo), hi_(hi), open_lo_(open_lo), open_hi_(open_hi) {}
  double lo_ = -inf, hi_ = inf;
  bool open_lo_ = false, open_hi_ = false;
};

class Reader {
 public:
  // `path` is the dotted path of `map` in the file ("" for the top level). Throws
  // SceneError if `map` is not a mapping or repeats a key.
  Reader(YAML::Node map, std::string file, std::string path);

  std::string path(const std::string& key) const;  // "coupling" + "window" -> "coupling.window"
  std::vector<std::string> keys() const;           // in file order; reading none of them

  // Getters without a fallback require the key. Every getter marks the key as read and as
  // known (has() marks it known), which is what finish() checks and lists.
  bool has(const std::string& key) const;
  double number(const std::string& key, const Range& range = {}) const;  // finite
  double number(const std::string& key, double fallback, const Range& range = {}) const;
  int integer(const std::string& key, const Range& range = {}) const;  // rejects 2.5
  int integer(const std::string& key, int fallback, const Range& range = {}) const;
  std::string string(const std::string& key) const;
  std::string string(const std::string& key, const std::string& fallback) const;
  bool boolean(const std::string& key) const;
  bool boolean(const std::string& key, bool fallback) const;
  Vec3 vec3(const std::string& key, const Range& range = {}) const;
  Vec3 vec3(const std::string& key, const Vec3& fallback, const Range& range = {}) const;
  void numbers(const std::string& key, std::span<double> out, const Range& range = {}) const;  // exactly out.size()
  void integers(const std::string& key, std::span<int> out, const Range& range = {}) const;    // exactly out.size()
  std::vector<std::string> strings(const std::string& key) const;
  // One of `names`, returned as its index (enum tables index by value).
  std::size_t choice(const std::string& key, std::span<const char* const> names) const;
  std::size_t choice(const std::string& key, std::span<const char* const> names, std::size_t fallback) const;
  // A list of distinct entries of `names`, as indices in file order.
  std::vector<std::size_t> choices(const std::string& key, std::span<const char* const> names) const;
  Reader map(const std::string& key) const;                // required sub-mapping
  std::vector<Reader> maps(const std::string& key) const;  // a list of mappings: "bodies[2]"
  YAML::Node node(const std::string& key) const;           // raw, required

  int line(const std::string& key) const;           // 1-based line of the key, or of this mapping if absent
  std::string where(const std::string& key) const;  // "file:line: path.key", for warnings
  [[noreturn]] void fail(const std::string& key, const std::string& problem) const;
  // Throws for the first key (in file order) present but never read:
  // "unknown key; expected one of: a, b, c".
  void finish() const;

 private:
  struct Entry {
    std::string key;
    YAML::Node key_node;
    YAML::Node value;
  };
  const Entry* find(const std::string& key) const;      // no bookkeeping
  const YAML::Node& get(const std::string& key) const;  // required: marks read, fails if absent
  double finite(const std::string& key) const;
  double checked(const std::string& key, double value, const Range& range) const;
  [[noreturn]] void fail_item(const std::string& key, std::size_t index, const std::string& problem) const;

  YAML::Node map_;
  std::string file_;
  std::string path_;
  std::vector<Entry> entries_;
  mutable std::vector<std::string> known_;  // asked for, in order of asking
  mutable std::set<std::string> read_;
};

// The `options` of a participant, ready to be read and finish()ed by its program.
Reader options_of(const Scene& scene, const Participant& participant);

}  // namespace cosim::scene
