#include "coupler/study/measure.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <stdexcept>

#include "coupler/output/body_series.hpp"
#include "coupler/output/field_means.hpp"
#include "coupler/study/argument_error.hpp"

namespace cosim::study {
namespace {

using Op = Expression::Op;

constexpr std::array<const char*, 5> kDatasets = {"position", "velocity", "angular_velocity", "force", "torque"};
constexpr std::array<const char*, 3> kComponents = {"x", "y", "z"};

struct Function {
  const char* name;
  Op op;
};
constexpr std::array<Function, 5> kFunctions = {
    {{"max", Op::Max}, {"min", Op::Min}, {"final", Op::Final}, {"mean", Op::Mean}, {"abs", Op::Abs}}};

class Parser {
 public:
  explicit Parser(const std::string& text) : text_(text) {}

  Expression measure() {
    Expression e = expression();
    skip_space();
    if (pos_ < text_.size()) fail(pos_, "expected the end of the measure");
    if (e.is_series())
      fail(0, "a series is one number per window: take max(...), min(...), final(...) or mean(..., t0, t1) of it");
    return e;
  }

 private:
  Expression expression() {
    skip_space();
    const std::size_t start = pos_;
    const std::string word = word_at();
    if (word == "body") {
      expect(':');
      return series();
    }
    if (word == "field") {
      expect(':');
      return field();
    }
    const auto f =
        std::find_if(kFunctions.begin(), kFunctions.end(), [&](const Function& f) { return word == f.name; });
    if (f == kFunctions.end())
      fail(start, word.empty() ? "expected max, min, final, mean, abs, body:NAME:DATASET.COMPONENT or "
                                 "field:PARTICIPANT:FIELD[.COMPONENT]"
                               : fmt::format("unknown function '{}'; expected max, min, final, mean or abs", word));
    Expression e;
    e.op = f->op;
    expect('(');
    skip_space();
    const std::size_t arg_start = pos_;
    Expression arg = expression();
    if (e.op != Op::Abs && !arg.is_series())
      fail(arg_start, fmt::format("{}() takes a series (body:NAME:DATASET.COMPONENT, field:PARTICIPANT:FIELD), not a "
                                  "number",
                                  word));
    if (e.op == Op::Mean) {
      expect(',');
      skip_space();
      const std::size_t t0_start = pos_;
      e.t0 = number("a time in seconds");
      expect(',');
      skip_space();
      const std::size_t t1_start = pos_;
      e.t1 = number("a time in seconds");
      if (e.t0 < 0) fail(t0_start, "mean() needs t0 >= 0");
      if (e.t1 <= e.t0) fail(t1_start, fmt::format("mean() needs t1 > t0 (t0 = {})", e.t0));
    }
    expect(')');
    e.arg = std::make_shared<const Expression>(std::move(arg));
    return e;
  }

  // A body's or a participant's name: letters, digits, '_' and '-'.
  std::string name_after(const char* what) {
    const std::size_t start = pos_;
    while (pos_ < text_.size() &&
           (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_' || text_[pos_] == '-'))
      ++pos_;
    if (pos_ == start) fail(start, fmt::format("expected a {}", what));
    return text_.substr(start, pos_ - start);
  }

  // After "field:".
  Expression field() {
    Expression e;
    e.participant = name_after("participant's name after 'field:'");
    expect(':');
    const std::size_t field_start = pos_;
    e.dataset = word_at();
    if (e.dataset.empty()) fail(field_start, "expected a field's name (velocity, pressure, density, ...)");
    e.column = -1;
    if (pos_ < text_.size() && text_[pos_] == '.') {
      ++pos_;
      e.column = component();
    }
    if (pos_ < text_.size() && text_[pos_] == '@') {
      ++pos_;
      e.region = region();
    }
    return e;
  }

  // After '@': a point [x, y, z], or a box [x0, y0, z0]..[x1, y1, z1].
  output::Region region() {
    output::Region r;
    r.lo = r.hi = point();
    if (text_.compare(pos_, 2, "..") == 0) {
      pos_ += 2;
      skip_space();
      const std::size_t hi_start = pos_;
      r.hi = point();
      for (int a = 0; a < 3; ++a)
        if (r.hi[a] <= r.lo[a]) fail(hi_start, "a box's upper corner must exceed its lower one on every axis");
    }
    return r;
  }

  std::array<double, 3> point() {
    expect('[');
    std::array<double, 3> p{};
    for (int a = 0; a < 3; ++a) {
      if (a > 0) expect(',');
      p[a] = number("a coordinate in metres");
    }
    expect(']');
    return p;
  }

  int component() {
    const std::size_t start = pos_;
    const auto c = std::find(kComponents.begin(), kComponents.end(), word_at());
    if (c == kComponents.end()) fail(start, "expected the component x, y or z");
    return static_cast<int>(c - kComponents.begin());
  }

  // After "body:".
  Expression series() {
    Expression e;
    e.body = name_after("body's name after 'body:'");
    expect(':');
    const std::size_t dataset_start = pos_;
    e.dataset = word_at();
    if (std::find(kDatasets.begin(), kDatasets.end(), e.dataset) == kDatasets.end())
      fail(dataset_start, "expected position, velocity, angular_velocity, force or torque");
    expect('.');
    e.column = component();
    return e;
  }

  // Letters and '_': a function, "body", a dataset or a component.
  std::string word_at() {
    const std::size_t start = pos_;
    while (pos_ < text_.size() && (std::isalpha(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_')) ++pos_;
    return text_.substr(start, pos_ - start);
  }

  double number(const char* what) {
    skip_space();
    double value = 0;
    const char* begin = text_.data() + pos_;
    const auto [end, ec] = std::from_chars(begin, text_.data() + text_.size(), value);
    if (ec != std::errc() || !std::isfinite(value)) fail(pos_, fmt::format("expected {}", what));
    pos_ += static_cast<std::size_t>(end - begin);
    return value;
  }

  void expect(char c) {
    skip_space();
    if (pos_ >= text_.size() || text_[pos_] != c) fail(pos_, fmt::format("expected '{}'", c));
    ++pos_;
  }

  void skip_space() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }

  [[noreturn]] void fail(std::size_t at, const std::string& problem) const {
    if (at >= text_.size()) throw ArgumentError("at the end: " + problem);
    throw ArgumentError(fmt::format("at '{}': {}", text_.substr(at), problem));
  }

  const std::string& text_;
  std::size_t pos_ = 0;
};

struct Samples {
  std::vector<double> time, value;
};

Samples samples(const Expression& e, const std::filesystem::path& file) {
  if (e.op == Op::Abs) {
    Samples s = samples(*e.arg, file);
    for (double& v : s.value) v = std::abs(v);
    return s;
  }
  if (!e.participant.empty()) {
    const output::FieldMeans means = output::field_means(file, e.participant, e.dataset, e.region);
    const std::string where = fmt::format("{}: field:{}:{}", file.string(), e.participant, e.dataset);
    if (e.column < 0 && means.columns != 1)
      throw std::runtime_error(fmt::format("{} has {} components: name one (.x, .y, .z)", where, means.columns));
    if (e.column >= 0 && static_cast<std::size_t>(e.column) >= means.columns)
      throw std::runtime_error(
          fmt::format("{} has {} component{}", where, means.columns, means.columns > 1 ? "s" : ""));
    Samples s{means.time, {}};
    const auto column = static_cast<std::size_t>(std::max(e.column, 0));
    for (std::size_t row = 0; row < means.time.size(); ++row)
      s.value.push_back(means.values[row * means.columns + column]);
    return s;
  }
  const output::BodySeries series = output::body_series(file, e.body, e.dataset);
  Samples s{series.time, {}};
  for (std::size_t row = 0; row < series.time.size(); ++row)
    s.value.push_back(series.values[row * series.columns + static_cast<std::size_t>(e.column)]);
  if (s.time.empty()) throw std::runtime_error(file.string() + ": no row written for body " + e.body);
  return s;
}

// Linear between the rows around t (time is increasing, t within it).
double at(const Samples& s, double t) {
  const auto after = std::upper_bound(s.time.begin(), s.time.end(), t);
  if (after == s.time.begin()) return s.value.front();
  if (after == s.time.end()) return s.value.back();
  const auto i = static_cast<std::size_t>(after - s.time.begin());
  const double w = (t - s.time[i - 1]) / (s.time[i] - s.time[i - 1]);
  return s.value[i - 1] + w * (s.value[i] - s.value[i - 1]);
}

double mean(const Samples& s, double t0, double t1, const std::filesystem::path& file) {
  // Rows' times are sums of windows: 10 x 1.5e-4 is written 0.0014999999999999998, and a
  // mean to time.end must still reach the last row.
  const double slack = 1e-9 * (std::abs(s.time.front()) + std::abs(s.time.back()));
  if (t0 < s.time.front() - slack || t1 > s.time.back() + slack)
    throw std::runtime_error(fmt::format("{}: mean over [{}, {}] s reaches beyond the rows written, [{}, {}] s",
                                         file.string(), t0, t1, s.time.front(), s.time.back()));
  std::vector<std::pair<double, double>> points{{t0, at(s, t0)}};
  for (std::size_t i = 0; i < s.time.size(); ++i)
    if (s.time[i] > t0 && s.time[i] < t1) points.emplace_back(s.time[i], s.value[i]);
  points.emplace_back(t1, at(s, t1));
  double integral = 0;
  for (std::size_t i = 1; i < points.size(); ++i)
    integral += 0.5 * (points[i].second + points[i - 1].second) * (points[i].first - points[i - 1].first);
  return integral / (t1 - t0);
}

}  // namespace

bool Expression::is_series() const { return op == Op::Series || (op == Op::Abs && arg->is_series()); }

Measure parse_measure(const std::string& name, const std::string& text) { return {name, text, Parser(text).measure()}; }

std::vector<std::string> bodies_of(const Expression& e) {
  if (e.op == Op::Series) return e.participant.empty() ? std::vector<std::string>{e.body} : std::vector<std::string>{};
  return bodies_of(*e.arg);
}

std::vector<std::string> participants_of(const Expression& e) {
  if (e.op == Op::Series)
    return e.participant.empty() ? std::vector<std::string>{} : std::vector<std::string>{e.participant};
  return participants_of(*e.arg);
}

const output::Region* region_of(const Expression& e) {
  if (e.op == Op::Series) return e.participant.empty() ? nullptr : &e.region;
  return region_of(*e.arg);
}

double latest_time(const Expression& e) {
  if (e.op == Op::Mean) return e.t1;
  return e.op == Op::Series ? 0.0 : latest_time(*e.arg);
}

double evaluate(const Expression& e, const std::filesystem::path& run_file) {
  switch (e.op) {
    case Op::Abs:
      return std::abs(evaluate(*e.arg, run_file));
    case Op::Max: {
      const Samples s = samples(*e.arg, run_file);
      return *std::max_element(s.value.begin(), s.value.end());
    }
    case Op::Min: {
      const Samples s = samples(*e.arg, run_file);
      return *std::min_element(s.value.begin(), s.value.end());
    }
    case Op::Final:
      return samples(*e.arg, run_file).value.back();
    case Op::Mean:
      return mean(samples(*e.arg, run_file), e.t0, e.t1, run_file);
    case Op::Series:
      break;
  }
  throw std::logic_error("a series has no single value");  // parse_measure() refuses one
}

}  // namespace cosim::study
