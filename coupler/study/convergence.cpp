#include "coupler/study/convergence.hpp"

#include <cmath>

namespace cosim::study {
namespace {

// The paper's iteration (its Eqs. 3a-c): p = |ln|e32/e21| + q(p)| / ln r21 with
// q(p) = ln((r21^p - s) / (r32^p - s)). It starts at p = 1 (q is 0/0 at p = 0 when s = 1)
// and is a contraction for the ratios of practical refinements; one that does not settle
// within the bound has no order to report.
std::optional<double> fixed_point_order(double ratio, double s, double r21, double r32) {
  double p = 1;
  for (int i = 0; i < 1000; ++i) {
    const double q = std::log((std::pow(r21, p) - s) / (std::pow(r32, p) - s));
    const double next = std::abs(std::log(ratio) + q) / std::log(r21);
    if (!std::isfinite(next)) return std::nullopt;
    if (std::abs(next - p) <= 1e-12 * (1 + next)) return next;
    p = next;
  }
  return std::nullopt;
}

}  // namespace

const char* to_string(Convergence c) {
  switch (c) {
    case Convergence::Monotonic:
      return "monotonic convergence";
    case Convergence::Oscillatory:
      return "oscillatory convergence";
    case Convergence::Diverging:
      return "diverging";
    case Convergence::Unchanged:
      return "unchanged";
  }
  return "?";
}

Estimate estimate(double phi1, double phi2, double phi3, double r21, double r32) {
  Estimate e;
  e.extrapolate = phi1;
  const double e21 = phi2 - phi1;
  const double e32 = phi3 - phi2;
  if (e21 == 0) return e;  // Unchanged
  const double s = e32 / e21 < 0 ? -1.0 : 1.0;
  const double ratio = std::abs(e32 / e21);
  // The paper's absolute value makes p positive even when the levels move apart. Its model,
  // phi_i = phi_ext + C (s)^i h_i^p, gives |e32 / e21| = r21^p (r32^p - s) / (r21^p - s),
  // which grows with p from ln r32 / ln r21 (s = 1) or 1 (s = -1) at p = 0: a smaller
  // ratio means p < 0, a fine pair further apart than the coarse one.
  const double at_zero = s > 0 ? std::log(r32) / std::log(r21) : 1.0;
  e.e_a21 = std::abs(e21 / phi1);
  if (ratio <= at_zero) {
    e.convergence = Convergence::Diverging;
    return e;
  }
  e.convergence = s > 0 ? Convergence::Monotonic : Convergence::Oscillatory;
  e.order = fixed_point_order(ratio, s, r21, r32);
  if (!e.order) return e;
  const double rp = std::pow(r21, *e.order);
  e.extrapolate = (rp * phi1 - phi2) / (rp - 1);
  e.e_ext21 = std::abs((e.extrapolate - phi1) / e.extrapolate);
  e.gci_fine = 1.25 * e.e_a21 / (rp - 1);
  e.gci_fine_abs = 1.25 * std::abs(e21) / (rp - 1);
  return e;
}

}  // namespace cosim::study
