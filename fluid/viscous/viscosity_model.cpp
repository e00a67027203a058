#include "fluid/viscous/viscosity_model.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cosim::fluid::viscous {

ViscosityModel::ViscosityModel(Kind kind, double a, double b, double c, double d)
    : kind_(kind), a_(a), b_(b), c_(c), d_(d) {}

ViscosityModel ViscosityModel::newtonian(double mu) {
  if (!(mu > 0)) throw std::invalid_argument("viscosity: mu must be > 0");
  return {Kind::newtonian, mu, 0, 0, 0};
}

ViscosityModel ViscosityModel::power_law(double consistency, double index, double mu_min, double mu_max) {
  if (!(consistency > 0) || !(index > 0) || !(mu_min > 0) || !(mu_max >= mu_min))
    throw std::invalid_argument("power-law viscosity: need K > 0, n > 0 and 0 < mu_min <= mu_max");
  return {Kind::power_law, consistency, index, mu_min, mu_max};
}

ViscosityModel ViscosityModel::carreau(double mu_zero, double mu_infinity, double time_constant, double index) {
  if (!(mu_zero > 0) || !(mu_infinity > 0) || !(time_constant >= 0) || !(index > 0))
    throw std::invalid_argument("Carreau viscosity: need mu_0 > 0, mu_inf > 0, lambda >= 0 and n > 0");
  return {Kind::carreau, mu_zero, mu_infinity, time_constant, index};
}

double ViscosityModel::operator()(double shear_rate) const {
  switch (kind_) {
    case Kind::newtonian:
      return a_;
    case Kind::power_law:
      return std::clamp(a_ * std::pow(shear_rate, b_ - 1), c_, d_);
    case Kind::carreau:
      return b_ + (a_ - b_) * std::pow(1 + (c_ * shear_rate) * (c_ * shear_rate), (d_ - 1) / 2);
  }
  return a_;
}

}  // namespace cosim::fluid::viscous
