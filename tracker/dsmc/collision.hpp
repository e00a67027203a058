#pragma once
// Binary collision models of DSMC for one species (equal masses): hard sphere, variable
// hard sphere (VHS) and variable soft sphere (VSS), after Bird (1994), ch. 2 and 4.

#include "tracker/dsmc/random.hpp"
#include "tracker/dsmc/species.hpp"
#include "tracker/types.hpp"

namespace cosim::tracker::dsmc {

enum class Model { hard_sphere, vhs, vss };

class CollisionModel {
 public:
  // Constant cross-section pi d^2, isotropic scattering.
  static CollisionModel hard_sphere(double mass, double diameter);
  // sigma(g) = pi d_ref^2 (2 k T_ref / (m_r g^2))^(omega - 1/2) / Gamma(5/2 - omega), with
  // the reduced mass m_r = m / 2; isotropic scattering.
  static CollisionModel vhs(double mass, double d_ref, double omega, double T_ref);
  // The VHS cross-section with the VSS diameter; deflection cos chi = 2 R^(1/alpha) - 1.
  static CollisionModel vss(double mass, double d_ref, double omega, double T_ref, double alpha);
  // From a species: VHS uses diameter_vhs, VSS diameter_vss (both with omega, T_ref); the
  // hard sphere takes diameter_vhs, which gives it the VHS collision rate at T_ref.
  static CollisionModel from_species(const Species& species, Model model);

  Model model() const { return model_; }
  double mass() const { return mass_; }
  double omega() const { return omega_; }
  double alpha() const { return alpha_; }
  double diameter() const { return diameter_; }
  double T_ref() const { return T_ref_; }

  // Total cross-section sigma(g) [m^2] and sigma(g) g [m^3/s] at relative speed g > 0.
  double cross_section(double g) const;
  double sigma_g(double g) const;
  // Equilibrium <sigma g> at temperature T (Bird eq. 4.64 divided by n):
  // 4 d^2 sqrt(pi k T_ref / m) (T / T_ref)^(1 - omega); for the hard sphere sigma <g>.
  double mean_sigma_g(double T) const;

  // Post-collision velocities of a pair: the centre-of-mass velocity is kept, the relative
  // velocity keeps its magnitude and turns by the deflection angle chi about a uniform
  // azimuth (isotropic for HS and VHS). Momentum and energy are conserved to round-off.
  void scatter(Vec3& v1, Vec3& v2, Rng& rng) const;
  // The new relative velocity for relative velocity g (the part of scatter that draws).
  Vec3 scattered(const Vec3& g, Rng& rng) const;

 private:
  Model model_ = Model::hard_sphere;
  double mass_ = 0, diameter_ = 0, omega_ = 0.5, T_ref_ = 273, alpha_ = 1;
  double sigma_g_factor_ = 0;  // sigma g = factor * g^(2 - 2 omega)
  double g_exponent_ = 1;      // 2 - 2 omega
  double inv_alpha_ = 1;
};

}  // namespace cosim::tracker::dsmc
