#include "tracker/dsmc/collision.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace cosim::tracker::dsmc {
namespace {

void check(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("CollisionModel: " + what);
}

}  // namespace

CollisionModel CollisionModel::hard_sphere(double mass, double diameter) {
  check(mass > 0 && diameter > 0, "hard sphere needs mass > 0 and diameter > 0");
  CollisionModel m;
  m.model_ = Model::hard_sphere;
  m.mass_ = mass;
  m.diameter_ = diameter;
  m.omega_ = 0.5;
  m.T_ref_ = 273;
  m.alpha_ = 1;
  m.inv_alpha_ = 1;
  m.g_exponent_ = 1;
  m.sigma_g_factor_ = std::numbers::pi * diameter * diameter;
  return m;
}

CollisionModel CollisionModel::vhs(double mass, double d_ref, double omega, double T_ref) {
  return vss(mass, d_ref, omega, T_ref, 1.0);
}

CollisionModel CollisionModel::vss(double mass, double d_ref, double omega, double T_ref, double alpha) {
  check(mass > 0 && d_ref > 0 && T_ref > 0, "VHS/VSS needs mass, d_ref and T_ref > 0");
  check(omega >= 0.5 && omega <= 1, "omega must lie in [0.5, 1], got " + std::to_string(omega));
  check(alpha >= 1 && alpha <= 2, "alpha must lie in [1, 2], got " + std::to_string(alpha));
  CollisionModel m;
  m.model_ = alpha == 1 ? Model::vhs : Model::vss;
  m.mass_ = mass;
  m.diameter_ = d_ref;
  m.omega_ = omega;
  m.T_ref_ = T_ref;
  m.alpha_ = alpha;
  m.inv_alpha_ = 1 / alpha;
  const double reduced = mass / 2;
  m.g_exponent_ = 2 - 2 * omega;
  // sigma g = pi d^2 (2 k T_ref / m_r)^(omega - 1/2) g^(1 - 2 omega) / Gamma(5/2 - omega) * g
  m.sigma_g_factor_ = std::numbers::pi * d_ref * d_ref * std::pow(2 * boltzmann * T_ref / reduced, omega - 0.5) /
                      std::tgamma(2.5 - omega);
  return m;
}

CollisionModel CollisionModel::from_species(const Species& s, Model model) {
  switch (model) {
    case Model::hard_sphere:
      return hard_sphere(s.mass, s.diameter_vhs);
    case Model::vhs:
      return vhs(s.mass, s.diameter_vhs, s.omega, s.T_ref);
    case Model::vss:
      return vss(s.mass, s.diameter_vss, s.omega, s.T_ref, s.alpha);
  }
  throw std::invalid_argument("CollisionModel: unknown model");
}

double CollisionModel::sigma_g(double g) const {
  if (model_ == Model::hard_sphere) return sigma_g_factor_ * g;
  return sigma_g_factor_ * std::pow(g, g_exponent_);
}

double CollisionModel::cross_section(double g) const { return sigma_g(g) / g; }

double CollisionModel::mean_sigma_g(double T) const {
  if (model_ == Model::hard_sphere)
    return std::numbers::pi * diameter_ * diameter_ * std::sqrt(16 * boltzmann * T / (std::numbers::pi * mass_));
  return 4 * diameter_ * diameter_ * std::sqrt(std::numbers::pi * boltzmann * T_ref_ / mass_) *
         std::pow(T / T_ref_, 1 - omega_);
}

Vec3 CollisionModel::scattered(const Vec3& g, Rng& rng) const {
  const double speed = g.norm();
  const double phi = 2 * std::numbers::pi * uniform(rng);
  const double s_phi = std::sin(phi), c_phi = std::cos(phi);
  if (model_ != Model::vss) {
    // Isotropic: a uniform direction on the sphere.
    const double c = 2 * uniform(rng) - 1;
    const double s = std::sqrt(std::max(0.0, 1 - c * c));
    return speed * Vec3(s * c_phi, s * s_phi, c);
  }
  // VSS: cos chi = 2 R^(1/alpha) - 1 about the direction of g, azimuth phi uniform.
  const double c = 2 * std::pow(uniform(rng), inv_alpha_) - 1;
  const double s = std::sqrt(std::max(0.0, 1 - c * c));
  if (speed == 0) return Vec3::Zero();
  const Vec3 e1 = g / speed;
  // An orthonormal basis around e1 without a singular direction (Duff et al. 2017).
  const double sign = std::copysign(1.0, e1.z());
  const double a = -1 / (sign + e1.z());
  const double b = e1.x() * e1.y() * a;
  const Vec3 e2(1 + sign * e1.x() * e1.x() * a, sign * b, -sign * e1.x());
  const Vec3 e3(b, sign + e1.y() * e1.y() * a, -e1.y());
  return speed * (c * e1 + s * (c_phi * e2 + s_phi * e3));
}

void CollisionModel::scatter(Vec3& v1, Vec3& v2, Rng& rng) const {
  const Vec3 centre = 0.5 * (v1 + v2);
  const Vec3 g = scattered(v1 - v2, rng);
  v1 = centre + 0.5 * g;
  v2 = centre - 0.5 * g;
}

}  // namespace cosim::tracker::dsmc
