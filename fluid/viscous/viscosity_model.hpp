#pragma once
// Dynamic viscosity as a function of the shear rate gamma = sqrt(2 D:D), D the strain-rate
// tensor: Newtonian, or generalized Newtonian (power law, Carreau).
namespace cosim::fluid::viscous {

class ViscosityModel {
 public:
  static ViscosityModel newtonian(double mu);
  // mu = K gamma^(n-1), clipped to [mu_min, mu_max]: the bare law is infinite (n < 1) or
  // zero (n > 1) in fluid at rest.
  static ViscosityModel power_law(double consistency, double index, double mu_min, double mu_max);
  // mu = mu_inf + (mu_0 - mu_inf) (1 + (lambda gamma)^2)^((n-1)/2)
  static ViscosityModel carreau(double mu_zero, double mu_infinity, double time_constant, double index);

  bool newtonian() const { return kind_ == Kind::newtonian; }
  double operator()(double shear_rate) const;

 private:
  enum class Kind { newtonian, power_law, carreau };
  ViscosityModel(Kind kind, double a, double b, double c, double d);
  Kind kind_;
  // newtonian: mu; power law: K, n, mu_min, mu_max; Carreau: mu_0, mu_inf, lambda, n
  double a_, b_, c_, d_;
};

}  // namespace cosim::fluid::viscous
