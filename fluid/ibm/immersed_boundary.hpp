#pragma once
// The immersed boundary method with multidirect forcing: bodies of any shape on the fixed
// grid, their force smooth in the pose (Uhlmann, J. Comput. Phys. 209 (2005) 448; Breugem,
// J. Comput. Phys. 231 (2012) 4469; Kempe & Froehlich, J. Comput. Phys. 231 (2012) 3663).
//
// Each body carries Lagrangian markers about one cell apart on its surface
// (surface_sampling.hpp) moved inside by the retraction (below), each standing for the
// volume dV_l = its share of the moved surface times the cell width across it. Inside every step, between the
// explicit right-hand side and the implicit viscous solve (BodyForcing), the markers'
// forces F_l are found such that the explicit estimate u~ with their spread force
//   u~ + dt sum_l F_l delta(x - X_l) dV_l
// interpolates to the body's velocity at every marker, U_l = sum_x u delta(x - X_l) h^3,
// and the force goes into the viscous solve's right-hand side. Multidirect forcing finds
// them by sweeps that each interpolate, correct F_l by the missing velocity over dt and
// spread the correction, so that every marker sees its neighbours' forcing; here that same
// linear system (symmetric in the impulses dt F_l dV_l) is assembled from the markers'
// kernels and solved by conjugate gradients with each body's block solved exactly
// (forcing_system.hpp), until the markers' velocity is met to `tolerance`. Each step
// starts from the forces of the last one, so a steady flow needs no iteration at all. A marker takes part on the ranks
// whose faces its kernel touches, its interpolated velocity summed over them (marker_sharing.hpp), so a rank's forcing
// work grows with the bodies near it and no ghost layer is needed whatever the kernel's width. The projection then runs
// over the whole domain with the fluid's own, never-changing operators.
//
// With `spread_at_theta` a moving body's markers interpolate where they are at the step's
// end, X_l (the no-slip holds there), and spread their impulses from where they were at
// t_n + theta dt, X_l - (1 - theta) dt U_l: the force acts over the step, and the step's
// viscous terms are centred there, so the fluid a step displaces is the fluid the body
// swept during it rather than the fluid at its end. B = I S is then unsymmetric and solved
// by GMRES; at theta = 1 both places are the end (bench/fluid_accuracy/README.md "Time step of a moving
// body" measures it).
//
// Load on a body: the reaction to the forcing plus the rate of change of the momentum of the
// fluid inside it, whose inertia is then the fluid's own (Kempe & Froehlich):
//   F = -rho sum_l F_l dV_l + rho d/dt int alpha u dV,
//   T = -rho sum_l (X_l - x_c) x F_l dV_l + rho d/dt int alpha (x - x_c) x u dV,
// alpha the volume fraction of volume_fraction.hpp, the derivative taken over the step. The
// fluid's body force (a driving pressure gradient over rho) acts inside the bodies too, so
// a body held against it feels it as the fluid it holds: the pressure gradient's force on
// its volume.
#include <array>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "fluid/bodies/body_forcing.hpp"
#include "fluid/bodies/body_treatment.hpp"
#include "fluid/grid/grid.hpp"
#include "fluid/ibm/body_distance.hpp"
#include "fluid/ibm/delta_kernel.hpp"
#include "fluid/ibm/forcing_system.hpp"
#include "fluid/ibm/kernel_stencil.hpp"
#include "fluid/ibm/marker_sharing.hpp"
#include "fluid/ibm/marker_stencils.hpp"
#include "fluid/ibm/volume_fraction.hpp"
#include "geometry/sampled_shapes.hpp"

namespace cosim::fluid::ibm {

// How deep the markers sit under the surface, in cell widths h: the kernel spreads a
// marker's force over a shell about as wide as itself, so the no-slip surface the markers
// make lies outside them, and further out on a curved surface, where the shell's outer half
// has more room than its inner one. So a marker moves in by
//   h (constant + curvature h kappa),   kappa = kappa_1 + kappa_2,
// the sum of the principal curvatures where it sits (2 / r on a sphere, 1 / r on a
// cylinder, the section's curvature on a two-dimensional grid). Where the surface is
// concave (kappa < 0: a container's wall, a hollow in a mesh) the no-slip surface lies
// further into the fluid the more it curves, not less, so there the slope is `concave`.
struct Retraction {
  double constant = 0;
  double curvature = 0;
  double concave = 0;
};

// Per kernel, the retraction calibrated on the Hasimoto array (`fluid_accuracy
// --calibrate`): for each kernel the constant and the convex slope, zeroing the mean error
// over sphere positions at d/h = 8 and 12 (the wider kernels' markers go deeper, as their
// shell is thicker); the concave slope zeroes the flow rate of Poiseuille's flow in a round
// pipe at D/h 20 (tests/fluid/ibm_container_test.cpp, which validates it at D/h 30 and 40).
Retraction calibrated_retraction(DeltaKernel kernel);

struct IbmOptions {
  DeltaKernel kernel = DeltaKernel::roma3;
  int sweeps = 50;  // iterations of the forcing system per solve, at most
  // Largest slip at a marker, of the largest velocity there. The load moves with it by
  // steps as the iteration count changes, so implicit coupling, which iterates to 1e-4 of the
  // load, needs it well below that (at 1e-4 a window stalled at 1.6e-4).
  double tolerance = 1e-6;
  // After the projection the forcing corrects the slip the viscous solve and the projection
  // left (BodyForcing::correct): impulses found by FGMRES (options prefix `no_slip_`),
  // preconditioned by the forcing's own system, each iteration a viscous solve and a
  // projection of their field, at most `corrections` of them, to a root mean square slip
  // of `no_slip_tolerance` of the largest velocity at the markers. 0 (the default): the
  // forcing acts on the explicit estimate alone. Off by default: each costs a viscous solve
  // and a projection, and under implicit coupling a count that stops at a tolerance changes
  // with the pose and moves the load by steps below the coupling's tolerance, so a scene
  // that needs them asks for a fixed count.
  int corrections = 0;
  double no_slip_tolerance = 3e-3;
  // A moving body's markers spread their impulses from where they were at t_n + theta dt
  // (above) rather than from where they are at the step's end; off by default.
  bool spread_at_theta = false;
  std::optional<Retraction> retraction;  // unset: calibrated_retraction(kernel)
  double spacing = 1.0;                  // marker spacing in cell widths
};

class ImmersedBoundary final : public bodies::BodyTreatment, public bodies::BodyForcing {
 public:
  // grid must outlive this object. Throws std::invalid_argument for options out of range or
  // a grid it cannot work on (more than one flat axis, a periodic axis narrower than the
  // kernel's reach twice).
  explicit ImmersedBoundary(const grid::Grid& grid, IbmOptions options = {});

  // The markers add() gives `bodies` on a grid of `axes`, counted without a grid (whose
  // arrays a large one would make costly): what the forcing works on, for an estimate of a
  // run's cost. Throws as the constructor and add() do.
  static std::size_t marker_count(const grid::Axes& axes, const IbmOptions& options,
                                  std::span<const bodies::RigidBody> bodies);

  // Throws std::invalid_argument for a half-space, or a body none of whose markers stays
  // inside it once retracted (thinner than twice the retraction, or off a two-dimensional
  // grid's plane).
  std::size_t add(bodies::RigidBody body) override;
  void move(std::size_t body, const geometry::Pose& pose, const Eigen::Vector3d& velocity,
            const Eigen::Vector3d& angular_velocity) override;
  const bodies::RigidBody& body(std::size_t i) const override { return bodies_.at(i).body; }
  std::size_t size() const override { return bodies_.size(); }

  bodies::StepBodies for_step() override { return {.forcing = this}; }
  // Measured in the last step (zero before the first).
  std::vector<bodies::HydrodynamicLoad> loads(const navier_stokes::NavierStokes& flow) const override;
  std::vector<bodies::IndicatorPatch> cell_fractions(std::size_t i) const override;
  // Per body the inner fluid's momentum and angular momentum at the last step's end, and
  // its markers' forces.
  std::vector<double> state() const override;
  void restore(std::span<const double> state) override;

  void force(const navier_stokes::NavierStokes& flow, double dt, const bodies::ForcingArrays& arrays) override;
  int correct(const navier_stokes::NavierStokes& flow, double dt, bodies::StepResponse& response) override;
  void finish_step(const navier_stokes::NavierStokes& flow, double dt) override;

  // Body i's markers where it is now, world frame.
  std::vector<Eigen::Vector3d> markers(std::size_t i) const;
  // Largest |U_body - U_l| over the markers in the last step: on the explicit estimate the
  // forcing met (and the sweeps it took), and in the step's final velocity, after the
  // viscous solve, the projection and the corrections.
  double slip() const { return slip_; }
  double final_slip() const { return final_slip_; }
  int sweeps() const { return sweeps_; }
  // The markers this rank forced in the last step: those whose kernels touch its faces.
  std::size_t held_markers() const { return active_.size(); }
  const IbmOptions& options() const { return options_; }

 private:
  struct Marker {
    Eigen::Vector3d position, normal;  // body frame
    double area = 0;
    Eigen::Vector3d force = Eigen::Vector3d::Zero();  // F_l of the last step, world frame
    bool known = false;                               // this rank held it in the last step, so `force` is that step's
  };
  struct Entry {
    Entry(const grid::Grid& grid, bodies::RigidBody b) : body(std::move(b)), distance(grid, body) {}
    bodies::RigidBody body;
    BodyDistance distance;
    std::vector<Marker> markers;
    std::array<double, 6> inner{};  // int alpha u dV, int alpha (x - x_c) x u dV
    bool inner_known = false;
    Eigen::Vector3d forcing = Eigen::Vector3d::Zero(), forcing_moment = Eigen::Vector3d::Zero();  // sum F dV
    // alpha at this rank's faces of each component, where the body and its periodic images are
    std::array<std::vector<FractionImage>, 3> fraction;
    std::optional<geometry::Pose> fraction_pose;   // where the body was when `fraction` was found
    std::array<std::vector<grid::Index>, 3> held;  // a container's faces beyond its kernels (hold_solid)
    bodies::HydrodynamicLoad load;
  };
  static void check(const grid::Axes& axes, const IbmOptions& options);  // what the constructor refuses
  // The body's markers, placed about one cell apart on its surface and moved in by the
  // retraction (`options` resolved), the crowded ones thinned out.
  static std::vector<Marker> place_markers(const grid::Axes& axes, const IbmOptions& options,
                                           const bodies::RigidBody& body, const BodyDistance& distance,
                                           geometry::SampledShapes& sampled);
  // The markers whose kernels touch this rank's faces, of the bodies near it, where they are
  // (active_) or `lag` earlier, where they spread from (spreading_, the same markers).
  void collect_active_markers(double lag);
  bool bodies_move() const;  // any body has a velocity or an angular velocity
  const MarkerStencils& spreading() const { return spread_stencils_ ? *spread_stencils_ : *stencils_; }
  void update_fractions();  // of every body at this rank's faces, where it is now (and a container's held faces)
  // A container's solid beyond its markers' kernels is held at the container's velocity:
  // left free, the fluid there flows wherever a drive reaches it (a pipe's pressure
  // gradient, an inflow over a whole face) and leaks through the kernels' width into the
  // inside. Adds the impulses to `rhs` and to the container's forcing.
  void hold_solid(double dt, const bodies::ForcingArrays& arrays);
  std::vector<double> inner_momenta(const navier_stokes::NavierStokes& flow) const;  // 6 per body, summed over ranks
  // The interpolated velocity's misses at the markers (3 per marker), and their scale.
  double slip_in(const navier_stokes::NavierStokes& flow, const MarkerStencils& stencils,
                 std::vector<double>& residual) const;
  // Adds the markers' impulses dt F_l dV_l to their forces and their bodies' forcing (each
  // marker's share on this rank).
  void add_impulses(const std::vector<double>& g, double dt, const MarkerSharing& sharing);
  // The last step's forces of the active markers, agreed between their holders, as impulses.
  std::vector<double> last_impulses(const MarkerSharing& sharing, double dt) const;
  std::size_t total_markers() const { return first_marker_.empty() ? 0 : first_marker_.back(); }

  const grid::Grid& grid_;
  IbmOptions options_;
  std::vector<Entry> bodies_;
  geometry::SampledShapes sampled_;                // the bodies' shapes, sampled once each
  std::vector<ActiveMarker> active_;               // the markers taking part in the current step here
  std::vector<ActiveMarker> spreading_;            // the same markers where they spread from
  std::optional<MarkerStencils> stencils_;         // their kernels, made by force() for the step
  std::optional<MarkerStencils> spread_stencils_;  // the kernels they spread with, if elsewhere
  BodyBlockSolvers block_solvers_;                 // each body's block of it, kept from step to step
  std::optional<ForcingSystem> system_;            // and their forcing system
  std::vector<std::size_t> first_marker_{0};       // body b's markers are numbered from first_marker_[b]
  // The markers whose forces this rank holds from the last step (every marker after restore()).
  std::vector<std::pair<std::size_t, std::size_t>> held_;
  double slip_ = 0, final_slip_ = 0;
  int sweeps_ = 0;
};

}  // namespace cosim::fluid::ibm
