#include "coupler/target/error_model.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <stdexcept>

namespace cosim::target {

double Tolerance::absolute(double extrapolate) const { return relative ? value * std::abs(extrapolate) : value; }

Tolerance parse_tolerance(const std::string& text) {
  std::string number = text;
  while (!number.empty() && std::isspace(static_cast<unsigned char>(number.back()))) number.pop_back();
  const bool relative = !number.empty() && number.back() == '%';
  if (relative) number.pop_back();
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(number, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  while (used < number.size() && std::isspace(static_cast<unsigned char>(number[used]))) ++used;
  if (used == 0 || used != number.size() || !std::isfinite(value) || !(value > 0))
    throw std::invalid_argument(fmt::format(
        "tolerance '{}': expected a positive number, relative with a % sign (0.5%) or absolute in the quantity's unit "
        "(1e-4)",
        text));
  return {relative ? value / 100 : value, relative, text};
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
