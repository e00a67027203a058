// The error model behind `cosim run --target`: from three levels of one quantity, the
// resolution at which its discretization error meets a tolerance.
//
// Three levels at resolution scales s3 < s2 < s1 (s: how many times finer than the scene)
// give the observed order p and the extrapolate phi_ext (Celik et al., J. Fluids Eng. 130
// (2008) 078001; convergence.hpp). The error of a level at scale s is taken as
// |phi1 - phi_ext| (s1 / s)^p, the asymptotic model the extrapolate itself assumes, and the
// scale that reaches a tolerance is the one whose error times Celik's factor of safety 1.25
// (the GCI's) meets it.
#pragma once

#include <optional>
#include <string>

#include "coupler/study/convergence.hpp"

namespace cosim::target {

// "1%" or "0.5 %": relative to the extrapolate; "1e-4": absolute, in the quantity's unit.
struct Tolerance {
  double value = 0;
  bool relative = false;
  std::string text;  // as given
  double absolute(double extrapolate) const;
};

// Throws std::invalid_argument naming the text.
Tolerance parse_tolerance(const std::string& text);

// A finite number and the word after it, blanks around the word dropped: "10m" is 10, "m";
// none if the text does not start with a number.
struct Quantity {
  double value = 0;
  std::string unit;
};
std::optional<Quantity> number_and_unit(const std::string& text);

// Factor of safety on the modelled error (Celik et al.'s 1.25 for three levels).
inline constexpr double kSafety = 1.25;

struct Prediction {
  double order = 0;
  double extrapolate = 0;
  double tolerance = 0;     // absolute
  double finest_error = 0;  // |phi1 - phi_ext|, of the finest of the three levels
  double scale = 0;         // the resolution scale at which kSafety x error = tolerance
};

// From the finest three levels' estimate (e: phi1 the finest, at scale s1), or why there is
// none: the levels must converge monotonically with an order.
struct Fit {
  std::optional<Prediction> prediction;
  std::string why_none;
};
Fit predict(const study::Estimate& e, double phi1, double s1, const Tolerance& tolerance);

// The modelled error of a level at scale s, times kSafety: what --target holds against the
// tolerance before running.
double modelled_error(const Prediction& p, double s1, double s);

}  // namespace cosim::target
