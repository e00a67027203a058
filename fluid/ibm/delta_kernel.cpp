#include "fluid/ibm/delta_kernel.hpp"

#include <cmath>

namespace cosim::fluid::ibm {
namespace {

// K = 59/60 - sqrt(29)/20: the smallest second moment that keeps the kernel non-negative,
// and the one with three continuous derivatives.
double bao6_second_moment() { return 59.0 / 60 - std::sqrt(29.0) / 20; }

double roma3(double r) {
  if (r <= 0.5) return (1 + std::sqrt(1 - 3 * r * r)) / 3;
  if (r < 1.5) return (5 - 3 * r - std::sqrt(std::max(0.0, 1 - 3 * (1 - r) * (1 - r)))) / 6;
  return 0;
}

double peskin4(double r) {
  if (r <= 1) return (3 - 2 * r + std::sqrt(1 + 4 * r - 4 * r * r)) / 8;
  if (r < 2) return (5 - 2 * r - std::sqrt(std::max(0.0, -7 + 12 * r - 4 * r * r))) / 8;
  return 0;
}

// Bao et al. (2016), section 3: on each unit interval the six weights a marker at offset
// s in [0, 1] gives its neighbours follow from the moment conditions once the outermost one
// (phi(s - 3)) is known, and that one is the root of a quadratic from the sum-of-squares
// condition. The kernel is even, so phi(r) for r >= 0 takes the weights at distances s,
// 1 + s and 2 + s from the marker.
double bao6(double r) {
  if (r >= 3) return 0;
  const double k = bao6_second_moment();
  const int piece = r <= 1 ? 0 : (r <= 2 ? 1 : 2);
  const double s = r - piece, s2 = s * s, s3 = s2 * s;
  const double b = 9.0 / 4 - 1.5 * (k + s2) + (22.0 / 3 - 7 * k) * s - 7.0 / 3 * s3;
  const double c = 0.25 * ((161.0 / 36 - 59.0 / 6 * k + 5 * k * k) * 0.5 * s2 + (-109.0 / 24 + 5 * k) / 3 * s2 * s2 +
                           5.0 / 18 * s3 * s3);
  const double outer = (-b + std::sqrt(std::max(0.0, b * b - 112 * c))) / 56;  // phi(s - 3)
  switch (piece) {
    case 0:
      return 2 * outer + 5.0 / 8 - 0.25 * (k + s2);
    case 1:
      return -3 * outer + 0.25 - (4 - 3 * k) / 6 * s + s3 / 6;
    default:
      return outer - 1.0 / 16 + (k + s2) / 8 - (3 * k - 1) / 12 * s - s3 / 12;
  }
}

}  // namespace

std::string_view name(DeltaKernel kernel) {
  switch (kernel) {
    case DeltaKernel::roma3:
      return "roma3";
    case DeltaKernel::peskin4:
      return "peskin4";
    default:
      return "bao6";
  }
}

double support_radius(DeltaKernel kernel) {
  switch (kernel) {
    case DeltaKernel::roma3:
      return 1.5;
    case DeltaKernel::peskin4:
      return 2;
    default:
      return 3;
  }
}

double sum_of_squares(DeltaKernel kernel) {
  switch (kernel) {
    case DeltaKernel::roma3:
      return 0.5;
    case DeltaKernel::peskin4:
      return 3.0 / 8;
    default: {
      // The weights at offset 0 (0, K/8 - 1/16, 1/4, 5/8 - K/4, 1/4, K/8 - 1/16) squared.
      const double k = bao6_second_moment();
      return 67.0 / 128 - 11.0 / 32 * k + 3.0 / 32 * k * k;
    }
  }
}

double phi(DeltaKernel kernel, double r) {
  r = std::abs(r);
  switch (kernel) {
    case DeltaKernel::roma3:
      return roma3(r);
    case DeltaKernel::peskin4:
      return peskin4(r);
    default:
      return bao6(r);
  }
}

}  // namespace cosim::fluid::ibm
