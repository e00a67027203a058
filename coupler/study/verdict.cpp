#include "coupler/study/verdict.hpp"

#include <fmt/format.h>

#include <cmath>

namespace cosim::study {

std::string verdict(const Estimate& e, std::optional<double> expected, std::optional<double> previous) {
  switch (e.convergence) {
    case Convergence::Unchanged:
      return "unchanged: the two finest levels give the same value, so there is no order and no error estimate.";
    case Convergence::Diverging:
      return "diverging: the two finest levels differ more than the two coarsest (for their ratios), so the levels "
             "are not in the asymptotic range; no order, no extrapolate.";
    case Convergence::Oscillatory:
      if (!e.order) break;
      return fmt::format(
          "oscillatory convergence (e32/e21 < 0) at p = {:.3g}: the levels are not in the asymptotic "
          "range; p, the extrapolate and the GCI are rough guides only.",
          *e.order);
    case Convergence::Monotonic:
      break;
  }
  if (!e.order)
    return fmt::format("{}, but the fixed-point iteration for p does not settle: no order, no extrapolate.",
                       to_string(e.convergence));
  const double p = *e.order;
  std::string out = fmt::format("monotonic convergence at p = {:.3g}", p);
  if (previous && std::abs(p - *previous) > kOrderTolerance * p)
    return out + fmt::format(
                     ", but p was {:.3g} from the three levels before: it has not settled, so the levels are "
                     "not yet in the asymptotic range and the extrapolate and GCI are not to be trusted.",
                     *previous);
  if (!expected)
    return out +
           ". No expected order is given (--order, study.order), so whether the levels are in the asymptotic "
           "range is not judged.";
  if (std::abs(p - *expected) <= kOrderTolerance * *expected)
    return out + fmt::format(", within {:.0f} % of the expected order {:g}: the levels are in the asymptotic range.",
                             100 * kOrderTolerance, *expected);
  return out + fmt::format(
                   ", far from the expected order {:g}: the levels are not in the asymptotic range (refine "
                   "further, or the quantity converges at another order), and the extrapolate and GCI are "
                   "not to be trusted.",
                   *expected);
}

}  // namespace cosim::study
