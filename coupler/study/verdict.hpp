// What an estimate says, in words: the regime the levels are in, and how far to trust p,
// the extrapolate and the GCI.
#pragma once

#include <optional>
#include <string>

#include "coupler/study/convergence.hpp"

namespace cosim::study {

// Observed orders within this fraction of the expected order count as asymptotic.
inline constexpr double kOrderTolerance = 0.25;

// `expected`: the order the scheme should show (--order, study.order), if known;
// `previous`: the order from the three levels before the finest, with four or more levels.
// Under monotonic convergence, GCI_32 = r21^p GCI_21 (in the quantity's unit) holds for the
// observed p by construction: it is the equation p solves. So the order against the expected
// one is the check that carries information, and with more levels a p that moves from one
// triple of levels to the next.
std::string verdict(const Estimate& e, std::optional<double> expected, std::optional<double> previous);

}  // namespace cosim::study
