// The observed order of convergence, the Richardson extrapolate and the grid convergence
// index from three levels, by the procedure of Celik et al., "Procedure for estimation and
// reporting of uncertainty due to discretization in CFD applications", J. Fluids Eng. 130
// (2008) 078001. Level 1 is the finest here, as in the paper: phi1 fine, phi3 coarse; r21 =
// h2 / h1 and r32 = h3 / h2 (> 1), which may differ.
#pragma once

#include <optional>

namespace cosim::study {

enum class Convergence {
  Monotonic,    // e32 / e21 > 0 and the finer pair differs less (in proportion to the ratios)
  Oscillatory,  // e32 / e21 < 0, the finer pair differing less
  Diverging,    // the finer pair differs more than the coarser: no order, no extrapolate
  Unchanged,    // the two finer levels agree exactly: nothing to extrapolate
};

const char* to_string(Convergence c);

struct Estimate {
  Convergence convergence = Convergence::Unchanged;
  // The apparent order p, solved by the paper's fixed-point iteration; none when diverging,
  // unchanged, or when the iteration does not settle.
  std::optional<double> order;
  double extrapolate = 0;   // phi_ext^21 (phi1 without an order)
  double e_a21 = 0;         // |phi1 - phi2| / |phi1|, approximate relative error
  double e_ext21 = 0;       // |phi_ext - phi1| / |phi_ext|, extrapolated relative error
  double gci_fine = 0;      // 1.25 e_a21 / (r21^p - 1), relative to phi1
  double gci_fine_abs = 0;  // the same in the quantity's unit: 1.25 |phi1 - phi2| / (r21^p - 1)
};

Estimate estimate(double phi1, double phi2, double phi3, double r21, double r32);

}  // namespace cosim::study
