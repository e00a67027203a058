#include "coupler/scene/reader.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <errno.h>
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>

#include "coupler/scene/error.hpp"

namespace cosim::scene {
namespace {

// Messages quote values; a whole section pasted into one line helps nobody.
constexpr std::size_t max_value_chars = 40;

std::string shorten(std::string text) {
  if (text.size() > max_value_chars) text = text.substr(0, max_value_chars - 3) + "...";
  return text;
}

// The value as the user wrote it: scalars verbatim (quoted ones with their quotes, so that
// "expected a number" next to "0.5" makes sense), collections in flow form.
std::string text_of(const YAML::Node& node) {
  if (!node.IsDefined() || node.IsNull()) return "";
  if (node.IsScalar()) return shorten(node.Tag() == "!" ? "\"" + node.Scalar() + "\"" : node.Scalar());
  YAML::Emitter out;
  out.SetMapFormat(YAML::Flow);
  out.SetSeqFormat(YAML::Flow);
  out << node;
  return shorten(out.c_str());
}

int line_of(const YAML::Node& node) { return node.IsDefined() ? node.Mark().line + 1 : 0; }

// Plain scalars only: a quoted "1.5" is a string in YAML and stays one here.
std::optional<double> number_of(const YAML::Node& node) {
  double value = 0;
  if (!node.IsScalar() || node.Tag() == "!" || !YAML::convert<double>::decode(node, value)) return std::nullopt;
  return value;
}

std::string one_of(std::span<const char* const> names) {
  return fmt::format("expected one of: {}", fmt::join(names, ", "));
}

std::size_t index_of(std::span<const char* const> names, const std::string& name) {
  return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
}

// COSIM_SCENE_KEYS=<file> makes every getter append what it was asked to read, one line
// per call, so that scripts/scene_reference can list every key from the code that reads it.
// The programs `cosim check` starts inherit the variable and append to the same file; one
// write() per line with O_APPEND keeps their lines whole. Unset, a getter pays one branch.
int key_log() {
  static const int fd = [] {
    const char* file = std::getenv("COSIM_SCENE_KEYS");
    return file && *file ? ::open(file, O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC, 0644) : -1;
  }();
  return fd;
}

// Getters call each other (number with a fallback calls number, vec3 calls numbers); only
// the one the caller named records.
thread_local int depth = 0;

// The default as the user would write it.
std::string shown(double v) { return fmt::format("{}", v); }
std::string shown(int v) { return std::to_string(v); }
std::string shown(bool v) { return v ? "true" : "false"; }
std::string shown(const std::string& v) { return v.empty() ? "\"\"" : v; }
std::string shown(const Vec3& v) { return fmt::format("[{}]", fmt::join(v, ", ")); }
std::string shown(const char* v) { return v; }

// Records on construction, for the length of the getter's call, one tab-separated line:
// path, kind, "required" or "default" and the default, range, allowed names, program.
// `count` is the length of a list of numbers. has() records too (kind "has"): a key asked
// about before it is read is optional even where its getter takes no fallback.
class Note {
 public:
  template <class Fallback = int>
  Note(const Reader& r, const std::string& key, std::string_view kind, const Range* range = nullptr,
       const Fallback* fallback = nullptr, std::span<const char* const> names = {}, std::size_t count = 0)
      : on_(key_log() >= 0) {
    if (!on_ || depth++ > 0) return;
    const std::string line =
        fmt::format("{}\t{}{}\t{}\t{}\t{}\t{}\t{}\n", r.path(key), kind, count ? fmt::format(":{}", count) : "",
                    fallback ? "default" : "required", fallback ? shown(*fallback) : "",
                    range ? range->requirement() : "", fmt::join(names, ","), program_invocation_short_name);
    if (::write(key_log(), line.data(), line.size()) < 0) return;  // a lost line shows as a missing key
  }
  ~Note() {
    if (on_) --depth;
  }
  Note(const Note&) = delete;
  Note& operator=(const Note&) = delete;

 private:
  bool on_;
};

constexpr const int* none = nullptr;  // no fallback: the key is required

}  // namespace

bool Range::contains(double v) const { return (open_lo_ ? v > lo_ : v >= lo_) && (open_hi_ ? v < hi_ : v <= hi_); }

std::string Range::requirement() const {
  if (hi_ == inf) return fmt::format("must be {} {}", open_lo_ ? ">" : ">=", lo_);
  return fmt::format("must be in {}{}, {}{}", open_lo_ ? '(' : '[', lo_, hi_, open_hi_ ? ')' : ']');
}

Reader::Reader(YAML::Node map, std::string file, std::string path)
    : map_(std::move(map)), file_(std::move(file)), path_(std::move(path)) {
  if (!map_.IsDefined() || !map_.IsMap())
    throw SceneError(file_, line_of(map_), path_, text_of(map_), "expected a mapping");
  // yaml-cpp keeps the first of two equal keys without a word; a repeated key is almost
  // always an edit gone wrong, so refuse it.
  for (const auto& kv : map_) {
    if (!kv.first.IsScalar())
      throw SceneError(file_, line_of(kv.first), path_, text_of(kv.first), "expected a plain key");
    const std::string key = kv.first.Scalar();
    if (const Entry* first = find(key))
      throw SceneError(file_, line_of(kv.first), this->path(key), text_of(kv.second),
                       fmt::format("duplicate key (first at line {})", line_of(first->key_node)));
    entries_.push_back({key, kv.first, kv.second});
  }
}

std::string Reader::path(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

std::vector<std::string> Reader::keys() const {
  std::vector<std::string> out;
  for (const Entry& e : entries_) out.push_back(e.key);
  return out;
}

const Reader::Entry* Reader::find(const std::string& key) const {
  auto it = std::find_if(entries_.begin(), entries_.end(), [&](const Entry& e) { return e.key == key; });
  return it == entries_.end() ? nullptr : &*it;
}

bool Reader::has(const std::string& key) const {
  const Note note(*this, key, "has");
  if (std::find(known_.begin(), known_.end(), key) == known_.end()) known_.push_back(key);
  return find(key) != nullptr;
}

const YAML::Node& Reader::get(const std::string& key) const {
  if (!has(key)) fail(key, "missing required key");
  read_.insert(key);
  return find(key)->value;
}

double Reader::finite(const std::string& key) const {
  const std::optional<double> value = number_of(get(key));
  if (!value) fail(key, "expected a number");
  if (!std::isfinite(*value)) fail(key, "must be finite");
  return *value;
}

double Reader::checked(const std::string& key, double value, const Range& range) const {
  if (!range.contains(value)) fail(key, range.requirement());
  return value;
}

double Reader::number(const std::string& key, const Range& range) const {
  const Note note(*this, key, "number", &range);
  return checked(key, finite(key), range);
}

double Reader::number(const std::string& key, double fallback, const Range& range) const {
  const Note note(*this, key, "number", &range, &fallback);
  return has(key) ? number(key, range) : fallback;
}

int Reader::integer(const std::string& key, const Range& range) const {
  const Note note(*this, key, "integer", &range);
  const double value = finite(key);
  if (value != std::floor(value) || std::abs(value) > std::numeric_limits<int>::max()) fail(key, "expected an integer");
  return static_cast<int>(checked(key, value, range));
}

int Reader::integer(const std::string& key, int fallback, const Range& range) const {
  const Note note(*this, key, "integer", &range, &fallback);
  return has(key) ? integer(key, range) : fallback;
}

std::string Reader::string(const std::string& key) const {
  const Note note(*this, key, "string");
  const YAML::Node& node = get(key);
  if (!node.IsScalar()) fail(key, "expected a string");
  return node.Scalar();
}

std::string Reader::string(const std::string& key, const std::string& fallback) const {
  const Note note(*this, key, "string", nullptr, &fallback);
  return has(key) ? string(key) : fallback;
}

bool Reader::boolean(const std::string& key) const {
  const Note note(*this, key, "boolean");
  bool value = false;
  if (!YAML::convert<bool>::decode(get(key), value)) fail(key, "expected true or false");
  return value;
}

bool Reader::boolean(const std::string& key, bool fallback) const {
  const Note note(*this, key, "boolean", nullptr, &fallback);
  return has(key) ? boolean(key) : fallback;
}

void Reader::numbers(const std::string& key, std::span<double> out, const Range& range) const {
  const Note note(*this, key, "numbers", &range, none, {}, out.size());
  const YAML::Node& node = get(key);
  const std::string expected = fmt::format("expected a list of {} numbers", out.size());
  if (!node.IsSequence() || node.size() != out.size()) fail(key, expected);
  for (std::size_t i = 0; i < out.size(); ++i) {
    const std::optional<double> value = number_of(node[i]);
    if (!value || !std::isfinite(*value)) fail(key, expected);
    if (!range.contains(*value)) fail(key, "every entry " + range.requirement());
    out[i] = *value;
  }
}

void Reader::integers(const std::string& key, std::span<int> out, const Range& range) const {
  const Note note(*this, key, "integers", &range, none, {}, out.size());
  std::vector<double> values(out.size());
  numbers(key, values, range);
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (values[i] != std::floor(values[i]) || std::abs(values[i]) > std::numeric_limits<int>::max())
      fail(key, fmt::format("expected a list of {} integers", out.size()));
    out[i] = static_cast<int>(values[i]);
  }
}

Vec3 Reader::vec3(const std::string& key, const Range& range) const {
  const Note note(*this, key, "vec3", &range);
  Vec3 v{};
  numbers(key, v, range);
  return v;
}

Vec3 Reader::vec3(const std::string& key, const Vec3& fallback, const Range& range) const {
  const Note note(*this, key, "vec3", &range, &fallback);
  return has(key) ? vec3(key, range) : fallback;
}

std::vector<std::string> Reader::strings(const std::string& key) const {
  const Note note(*this, key, "strings");
  const YAML::Node& node = get(key);
  if (!node.IsSequence()) fail(key, "expected a list of strings");
  std::vector<std::string> out;
  for (const YAML::Node& item : node) {
    if (!item.IsScalar()) fail(key, "expected a list of strings");
    out.push_back(item.Scalar());
  }
  return out;
}

std::size_t Reader::choice(const std::string& key, std::span<const char* const> names) const {
  const Note note(*this, key, "choice", nullptr, none, names);
  const std::size_t i = index_of(names, string(key));
  if (i == names.size()) fail(key, one_of(names));
  return i;
}

std::size_t Reader::choice(const std::string& key, std::span<const char* const> names, std::size_t fallback) const {
  const Note note(*this, key, "choice", nullptr, &names[fallback], names);
  return has(key) ? choice(key, names) : fallback;
}

std::vector<std::size_t> Reader::choices(const std::string& key, std::span<const char* const> names) const {
  const Note note(*this, key, "choices", nullptr, none, names);
  const YAML::Node& node = get(key);
  if (!node.IsSequence()) fail(key, fmt::format("expected a list of: {}", fmt::join(names, ", ")));
  std::vector<std::size_t> out;
  for (std::size_t n = 0; n < node.size(); ++n) {
    const std::size_t i = node[n].IsScalar() ? index_of(names, node[n].Scalar()) : names.size();
    if (i == names.size()) fail_item(key, n, one_of(names));
    if (std::find(out.begin(), out.end(), i) != out.end()) fail_item(key, n, "listed twice");
    out.push_back(i);
  }
  return out;
}

Reader Reader::map(const std::string& key) const {
  const Note note(*this, key, "mapping");
  const YAML::Node& node = get(key);
  if (!node.IsMap()) fail(key, "expected a mapping");
  return Reader(node, file_, path(key));
}

std::vector<Reader> Reader::maps(const std::string& key) const {
  const Note note(*this, key, "mappings");
  const YAML::Node& node = get(key);
  if (!node.IsSequence()) fail(key, "expected a list of mappings");
  std::vector<Reader> out;
  for (std::size_t n = 0; n < node.size(); ++n) out.emplace_back(node[n], file_, fmt::format("{}[{}]", path(key), n));
  return out;
}

YAML::Node Reader::node(const std::string& key) const {
  const Note note(*this, key, "node");
  return get(key);
}

int Reader::line(const std::string& key) const {
  const Entry* e = find(key);
  return line_of(e ? e->key_node : map_);
}

std::string Reader::where(const std::string& key) const {
  return file_ + ":" + std::to_string(line(key)) + ": " + path(key);
}

void Reader::fail(const std::string& key, const std::string& problem) const {
  const Entry* e = find(key);
  throw SceneError(file_, line(key), path(key), e ? text_of(e->value) : "", problem);
}

void Reader::fail_item(const std::string& key, std::size_t index, const std::string& problem) const {
  const YAML::Node item = get(key)[index];
  throw SceneError(file_, line_of(item), fmt::format("{}[{}]", path(key), index), text_of(item), problem);
}

void Reader::finish() const {
  for (const Entry& e : entries_) {
    if (read_.contains(e.key)) continue;
    fail(e.key, known_.empty() ? "unknown key; none are expected here"
                               : fmt::format("unknown key; expected one of: {}", fmt::join(known_, ", ")));
  }
}

Reader options_of(const Scene& scene, const Participant& participant) {
  return Reader(participant.options, scene.file.string(), "participants." + participant.name + ".options");
}

}  // namespace cosim::scene
