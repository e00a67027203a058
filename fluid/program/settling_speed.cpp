#include "fluid/program/settling_speed.hpp"

#include <cmath>

namespace cosim::fluid::program {
namespace {

double drag_coefficient(double reynolds) {
  return reynolds > 1000 ? 0.44 : 24 / reynolds * (1 + 0.15 * std::pow(reynolds, 0.687));
}

// The Reynolds number at which the drag balances the weight less the buoyancy:
// (3/4) C_D(Re) Re^2 = Ar, Archimedes' number, rising with Re, by bisection.
double balance_reynolds(double archimedes) {
  double lo = 0, hi = 1;
  const auto excess = [&](double re) { return 0.75 * drag_coefficient(re) * re * re - archimedes; };
  while (excess(hi) < 0) hi *= 2;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (excess(mid) < 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

double settling_speed(double diameter, double body_density, double fluid_density,
                      const fluid::viscous::ViscosityModel& viscosity, double gravity) {
  const double excess = std::abs(body_density - fluid_density);
  if (!(excess > 0) || !(gravity > 0) || !(diameter > 0) || !(fluid_density > 0)) return 0;
  // A shear-thinning fluid's viscosity depends on the speed: a few rounds settle it.
  double speed = 0;
  for (int round = 0; round < 20; ++round) {
    const double mu = viscosity(speed > 0 ? speed / diameter : 1.0);
    const double archimedes = fluid_density * excess * gravity * diameter * diameter * diameter / (mu * mu);
    speed = balance_reynolds(archimedes) * mu / (fluid_density * diameter);
  }
  return speed;
}

}  // namespace cosim::fluid::program
