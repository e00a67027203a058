#pragma once
// Plane Couette and Fourier flow of a hard-sphere gas between two diffuse plates, y = 0 and
// y = H, periodic along x and z (one cell there, `cells` along y): the library's DSMC loop
// (move with patch tallies, sort, NTC collisions, cell sampling) on a case whose transport
// is known. Shared by the transport tests and bench/dsmc_study.

#include "tracker/dsmc/collision.hpp"

#include <cstdint>

namespace cosim::tracker::transport {

// Chapman-Enskog transport of hard spheres (Chapman & Cowling 1970, ch. 10; Bird 1994,
// eqs. 3.71-3.73): the first approximations mu1 = 5/16 sqrt(pi m k T) / (pi d^2) and
// k1 = 15/4 (k/m) mu1 times their higher-order factors 1.016 and 1.025.
struct HardSphereGas {
  double mass = 6.63e-26;                              // argon, kg
  double diameter = 4.17e-10;                          // Bird's VHS diameter of argon at 273 K, m
  double mean_free_path(double number_density) const;  // 1 / (sqrt(2) pi d^2 n)
  double mean_speed(double temperature) const;         // sqrt(8 k T / (pi m))
  double viscosity(double temperature) const;
  double conductivity(double temperature) const;
  dsmc::CollisionModel model() const { return dsmc::CollisionModel::hard_sphere(mass, diameter); }
};

struct ChannelSpec {
  HardSphereGas gas;
  double number_density = 1e21;  // mean, m^-3
  double knudsen = 0.05;         // mean free path at the mean density over H
  int cells = 60;                // along y
  double particles_per_cell = 20.0;
  double dt_over_collision_time = 0.25;  // dt / (lambda / c_mean) at the mean plate temperature
  double wall_speed = 0.0;               // the plates move along x at -U/2 (y = 0) and +U/2 (y = H)
  double lower_temperature = 273.0, upper_temperature = 273.0;  // K
  double bulk_margin = 3.0;  // mean free paths from each plate not in the profile fits
  int warm_up_steps = 400;
  int batches = 20;  // independent averages for the standard errors
  int batch_steps = 500;
  std::uint64_t seed = 1;
};

// The mean of the batches and its standard error.
struct Estimate {
  double mean = 0.0, error = 0.0;
};

struct ChannelResult {
  double width = 0.0;           // H, m
  double mean_free_path = 0.0;  // m
  double dt = 0.0;              // s
  std::size_t particles = 0;
  double wall_seconds = 0.0;
  double cpu_seconds = 0.0;  // of the process: the wall time less what others took on a shared machine
  long long lost = 0;
  // From the patch tallies: the x force per unit area the gas gives the lower plate and
  // minus that on the upper one (both the shear stress tau = mu du/dy at steady state), and
  // the heat per unit area and time the lower plate takes and the upper one gives (both
  // -q_y when no work is done).
  Estimate lower_shear, upper_shear, lower_heat, upper_heat;
  // From the cells: -P_xy and -q_y averaged over the channel (both uniform at steady state).
  // They are the kinetic parts only: a DSMC collision also moves momentum and energy across
  // the distance between its partners (up to a cell), which the plates see and which is
  // where the cell-size error of mu and k comes from (Alexander, Garcia & Alder 1998).
  Estimate bulk_shear, bulk_heat;
  // The DSMC transport coefficients over Chapman-Enskog's for hard spheres at the local
  // temperature (mu, k proportional to sqrt(T)): the plates' mean shear over mu(T) du/dy and
  // their mean heat over k(T) dT/dy, the gradients fitted over the bulk (bulk_margin from
  // the plates); 0 where the plates impose no gradient.
  Estimate viscosity_ratio, conductivity_ratio;
  double bulk_temperature = 0.0;  // mean over the bulk cells, K
};

ChannelResult run_channel(const ChannelSpec& spec);

// The free-molecular shear stress between diffuse plates in relative motion U:
// rho U sqrt(k T / (2 pi m)) (each plate takes the flux n c_mean / 4 and gives it U).
double free_molecular_shear(const HardSphereGas& gas, double number_density, double temperature, double wall_speed);

// The Navier-Stokes shear stress with velocity slip, mu U / (H + 2 zeta): zeta = k0
// sqrt(pi) / 2 lambda with k0 = 1.2540 for hard spheres and diffuse walls (Ohwada, Sone &
// Aoki 1989), 1.111 lambda.
double slip_shear(double viscosity, double wall_speed, double width, double mean_free_path);

// The Green-Kubo discretisation errors mu_DSMC / mu - 1 and k_DSMC / k - 1 of the spec's
// cell size dx and time step: 16 / (75 pi) (dx / lambda)^2 and 64 / (675 pi) (dx /
// lambda)^2 (Alexander, Garcia & Alder 1998), 16 / (75 pi) (c_mean dt / lambda)^2 and
// 32 / (225 pi) (c_mean dt / lambda)^2 (Hadjiconstantinou 2000; Garcia & Wagner 2000),
// c_mean dt / lambda being dt over the mean collision time; to second order they add. The
// papers were not at hand to check whether their speed is c_mean or the most probable
// sqrt(2 k T / m) = 0.886 c_mean: bench/dsmc_study measures 0.075-0.083 (dt / tau)^2 from
// dt = tau, against 0.068 for c_mean and 0.053 for the most probable speed.
double viscosity_error(const ChannelSpec& spec);
double conductivity_error(const ChannelSpec& spec);

}  // namespace cosim::tracker::transport
