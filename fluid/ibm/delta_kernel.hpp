#pragma once
// Regularized delta functions of the immersed boundary method: the one-dimensional
// kernel phi(r) (r in grid widths) whose tensor product phi(dx/h) phi(dy/h) phi(dz/h) / h^3
// interpolates the grid velocity to a Lagrangian marker and spreads the marker's force back.
// All three satisfy, for every shift of the marker against the grid,
//   sum_j phi(r - j) = 1,   sum_j (r - j) phi(r - j) = 0,   sum_j phi(r - j)^2 = C,
// the last making the kernel's self-weight independent of where the marker sits:
// - Roma, Peskin & Berger, J. Comput. Phys. 153 (1999) 509: 3 points, C = 1/2, continuous;
// - Peskin, Acta Numerica 11 (2002) 479: 4 points, C = 3/8, one continuous derivative;
// - Bao, Kaiser, Kaye & Peskin, J. Comput. Phys. 316 (2016) 139: 6 points, three
//   continuous derivatives, second moment K = 59/60 - sqrt(29)/20 and third moment zero too,
//   better translation invariance at twice the 4-point kernel's width.
#include <string_view>

namespace cosim::fluid::ibm {

enum class DeltaKernel { roma3, peskin4, bao6 };

// "roma3", "peskin4", "bao6".
std::string_view name(DeltaKernel kernel);
// Half-width of the support in grid widths: phi(r) = 0 for |r| >= radius.
double support_radius(DeltaKernel kernel);
// The kernel's constant sum of squares C (bao6: 67/128 - 11 K / 32 + 3 K^2 / 32).
double sum_of_squares(DeltaKernel kernel);
double phi(DeltaKernel kernel, double r);

}  // namespace cosim::fluid::ibm
