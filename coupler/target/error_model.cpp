#include "coupler/target/error_model.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <stdexcept>

namespace cosim::target {

double Tolerance::absolute(double extrapolate) const { return relative ? value * std::abs(extrapolate) : value; }

std::optional<Quantity> number_and_unit(const std::string& text) {
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  if (!std::isfinite(value)) return std::nullopt;
  std::string unit = text.substr(used);
  const auto blank = [](unsigned char c) { return std::isspace(c) != 0; };
  while (!unit.empty() && blank(unit.back())) unit.pop_back();
  while (!unit.empty() && blank(unit.front())) unit.erase(unit.begin());
  return Quantity{value, unit};
}

Tolerance parse_tolerance(const std::string& text) {
  const auto q = number_and_unit(text);
  if (!q || !(q->value > 0) || !(q->unit.empty() || q->unit == "%"))
    throw std::invalid_argument(fmt::format(
        "tolerance '{}': expected a positive number, relative with a % sign (0.5%) or absolute in the quantity's unit "
        "(1e-4)",
        text));
  const bool relative = q->unit == "%";
  return {relative ? q->value / 100 : q->value, relative, text};
}

Fit predict(const study::Estimate& e, double phi1, double s1, const Tolerance& tolerance) {
  if (e.convergence != study::Convergence::Monotonic || !e.order) {
    const char* how = e.convergence == study::Convergence::Oscillatory ? "oscillate about their limit"
                      : e.convergence == study::Convergence::Diverging ? "move apart"
                      : e.convergence == study::Convergence::Unchanged ? "do not change"
                                                                       : "converge without a settled order";
    return {std::nullopt, fmt::format("the three levels {}, so there is no error model to extrapolate from", how)};
  }
  Prediction p;
  p.order = *e.order;
  p.extrapolate = e.extrapolate;
  p.tolerance = tolerance.absolute(e.extrapolate);
  p.finest_error = std::abs(phi1 - e.extrapolate);
  if (!(p.tolerance > 0)) return {std::nullopt, "the extrapolate is 0, so a relative tolerance is 0"};
  p.scale = s1 * std::pow(kSafety * p.finest_error / p.tolerance, 1 / p.order);
  return {p, {}};
}

double modelled_error(const Prediction& p, double s1, double s) {
  return kSafety * p.finest_error * std::pow(s1 / s, p.order);
}

}  // namespace cosim::target
