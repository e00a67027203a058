#include "fluid/program/adapter.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "fluid/program/body_responses.hpp"
#include "fluid/program/body_surfaces.hpp"
#include "fluid/program/cell_fields.hpp"
#include "fluid/program/petsc_flags.hpp"
#include "coupler/participant/poses_at.hpp"

namespace cosim::fluid::program {
namespace {

void check_size(const std::vector<participant::PoseRow>& poses, std::size_t bodies) {
  if (poses.size() != bodies)
    throw std::runtime_error("poses for " + std::to_string(poses.size()) + " bodies, the scene has " +
                             std::to_string(bodies));
}

// Periodic axes have their faces from the grid already.
fluid::grid::BoundaryConditions boundary_conditions(const fluid::grid::Grid& grid, const FluidSetup& s) {
  fluid::grid::BoundaryConditions bc(grid);
  for (int a = 0; a < 3; ++a)
    if (!s.axes[static_cast<std::size_t>(a)].periodic())
      for (fluid::grid::Side side : {fluid::grid::Side::lower, fluid::grid::Side::upper})
        bc.set(a, side, s.boundaries[static_cast<std::size_t>(2 * a + static_cast<int>(side))]);
  return bc;
}

// The scene's grid.ranks for the DMDAs, or PETSc's choice where it has none.
std::array<PetscInt, 3> dmda_ranks(const FluidSetup& s) {
  if (s.ranks == std::array<int, 3>{}) return {PETSC_DECIDE, PETSC_DECIDE, PETSC_DECIDE};
  int size = 1;
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  if (s.ranks[0] * s.ranks[1] * s.ranks[2] != size)
    throw std::invalid_argument("participants.fluid.options.grid.ranks [" + std::to_string(s.ranks[0]) + ", " +
                                std::to_string(s.ranks[1]) + ", " + std::to_string(s.ranks[2]) +
                                "]: their product is not the " + std::to_string(size) + " ranks cosim-fluid runs on");
  return {s.ranks[0], s.ranks[1], s.ranks[2]};
}

}  // namespace

struct FluidSolver::Flow {
  explicit Flow(const FluidSetup& s)
      : grid(PETSC_COMM_WORLD, {s.axes[0], s.axes[1], s.axes[2]}, dmda_ranks(s)),
        bc(boundary_conditions(grid, s)),
        flow(grid, bc, s.properties, s.steps),
        bodies(fluid::make_bodies(grid, s.body_method)) {}

  fluid::grid::Grid grid;
  fluid::grid::BoundaryConditions bc;
  fluid::navier_stokes::NavierStokes flow;
  std::unique_ptr<fluid::bodies::BodyTreatment> bodies;
  std::unique_ptr<BodySurfaces> surfaces;  // once the bodies are added
  std::optional<BodyResponses> responses;  // with the immersed boundary, once the bodies are added
};

FluidSolver::FluidSolver(bool prescribed) : prescribed_(prescribed) {}
FluidSolver::~FluidSolver() = default;

const fluid::navier_stokes::NavierStokes& FluidSolver::flow() const { return flow_->flow; }

participant::Outputs FluidSolver::initialise(const scene::Scene& scene, const std::string&,
                                             const std::vector<participant::PoseRow>& poses,
                                             const std::vector<double>& state) {
  setup_ = fluid_setup(scene);
  // Before the solvers exist: they read the flags when they are created.
  insert_petsc_flags(setup_.petsc);
  flow_ = std::make_unique<Flow>(setup_);
  for (const fluid::bodies::RigidBody& b : setup_.bodies) flow_->bodies->add(b);
  flow_->surfaces = std::make_unique<BodySurfaces>(flow_->grid, *flow_->bodies, setup_.body_names);
  // Fixed bodies never move, so a scene of them alone (Hasimoto's array) needs no responses,
  // whose measurement runs 96 windows of the scene's steps.
  const bool moving = std::any_of(scene.bodies.begin(), scene.bodies.end(), [](const auto& b) { return !b.fixed; });
  if (std::holds_alternative<fluid::ibm::IbmOptions>(setup_.body_method) && moving) {
    std::vector<std::size_t> same_shape;
    std::vector<bool> fixed;
    for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
      fixed.push_back(scene.bodies[b].fixed);
      std::size_t first = 0;
      while (first < b && (scene.bodies[first].fixed || !(scene.bodies[first].shape == scene.bodies[b].shape))) ++first;
      same_shape.push_back(first);
    }
    flow_->responses.emplace(flow_->grid, setup_.bodies, same_shape, fixed, setup_.properties, setup_.steps,
                             setup_.body_method, scene.coupling.window);
  }
  const fluid::grid::Point u0 = setup_.initial_velocity;
  flow_->flow.set_velocity([&](const fluid::grid::Point&) { return u0; });
  // The coupler's poses (the rigid-body program's centres of mass) win over the scene's.
  place(prescribed_ || poses.empty() ? program::poses_at(setup_.motions, 0) : poses);
  if (!state.empty()) restore(state);
  const std::vector<participant::ForceRow> loads = forces();
  // Resumed, the coupler goes on with the committed forces and responses; rows made here
  // would move the responses' state on past the checkpoint's.
  return {prescribed_ ? poses_ : std::vector<participant::PoseRow>{}, loads, 0,
          state.empty() ? responses({}, loads) : std::vector<participant::ResponseRow>{}};
}

participant::Outputs FluidSolver::advance(const participant::Window& w, const participant::Inputs& in) {
  if (!in.poses_start.empty()) check_size(in.poses_start, setup_.bodies.size());
  // The window's mean load, the impulse over the window's length: a face switching between
  // fluid and solid gives the staircase FBM's load a one-step spike, which as the window-end
  // value would act on the body for the whole window.
  std::vector<participant::ForceRow> mean(setup_.bodies.size());
  // Where the bodies start the window: a repeated window's, not where its last iteration left them.
  const std::vector<participant::PoseRow> start = poses_at(w, in, w.t0);
  const double length = w.t1 - w.t0;
  const auto steps = flow_->flow.advance_to(
      w.t1, flow_->bodies->for_step(), [&](double t) { place(poses_at(w, in, t)); },
      [&](const fluid::navier_stokes::StepReport& r) {
        if (!std::isfinite(r.max_divergence))
          throw std::runtime_error("fluid diverged at t = " + std::to_string(r.time) + " (non-finite velocity)");
        const std::vector<participant::ForceRow> f = forces();
        for (std::size_t b = 0; b < f.size(); ++b) {
          mean[b].force += f[b].force * r.dt / length;
          mean[b].torque += f[b].torque * r.dt / length;
        }
      });
  steps_ += steps.size();
  for (const fluid::navier_stokes::StepReport& r : steps) stage_seconds_ += r.seconds;
  return {prescribed_ ? poses_ : std::vector<participant::PoseRow>{}, mean, static_cast<double>(steps.size()),
          responses(start, mean)};
}

std::vector<participant::PoseRow> FluidSolver::poses_at(const participant::Window& w, const participant::Inputs& in,
                                                        double t) const {
  if (prescribed_) return program::poses_at(setup_.motions, t);
  if (in.poses_start.empty()) return poses_;
  return participant::poses_at(in, w, t);
}

void FluidSolver::place(const std::vector<participant::PoseRow>& poses) {
  check_size(poses, setup_.bodies.size());
  poses_ = poses;
  for (std::size_t b = 0; b < poses.size(); ++b) {
    const participant::PoseRow& row = poses[b];
    flow_->bodies->move(b, geometry::Pose(row.position, row.orientation), row.velocity, row.angular_velocity);
  }
}

std::vector<participant::ForceRow> FluidSolver::forces() const {
  std::vector<participant::ForceRow> out;
  for (const fluid::bodies::HydrodynamicLoad& l : flow_->bodies->loads(flow_->flow)) out.push_back({l.force, l.torque});
  return out;
}

std::vector<participant::ResponseRow> FluidSolver::responses(const std::vector<participant::PoseRow>& start,
                                                             const std::vector<participant::ForceRow>& loads) {
  if (!flow_->responses) return {};
  const auto velocities = [](const std::vector<participant::PoseRow>& poses) {
    std::vector<BodyResponses::Vector6d> out;
    for (const participant::PoseRow& p : poses)
      out.push_back((BodyResponses::Vector6d() << p.velocity, p.angular_velocity).finished());
    return out;
  };
  std::vector<Eigen::Quaterniond> orientations;
  for (const participant::PoseRow& p : poses_) orientations.push_back(p.orientation);
  return flow_->responses->after(velocities(start), velocities(poses_), orientations, loads);
}

// Rank 0 alone fills the point sets (coupler/field/field_frame.hpp).
field::FieldFrame FluidSolver::fields() const {
  field::FieldFrame frame = cell_fields(flow_->flow, *flow_->bodies);
  PetscMPIInt rank = 0;
  MPI_Comm_rank(flow_->grid.comm(), &rank);
  if (rank == 0) frame.point_sets = flow_->surfaces->where(*flow_->bodies);
  return frame;
}

// The flow's state, the bodies' (the immersed boundary's inner-fluid momenta), the
// responses' (the changes of the motion over the last windows), then the responses' length.
std::vector<double> FluidSolver::state() const {
  std::vector<double> out = flow_->flow.state();
  const std::vector<double> bodies = flow_->bodies->state();
  const std::vector<double> responses = flow_->responses ? flow_->responses->state() : std::vector<double>{};
  out.insert(out.end(), bodies.begin(), bodies.end());
  out.insert(out.end(), responses.begin(), responses.end());
  out.push_back(static_cast<double>(responses.size()));
  return out;
}

void FluidSolver::restore(const std::vector<double>& state) {
  const std::size_t bodies = flow_->bodies->state().size();
  try {
    const double length = state.empty() ? -1 : state.back();
    if (!(length >= 0 && length + 1 + static_cast<double>(bodies) <= static_cast<double>(state.size())))
      throw std::invalid_argument("too short for its parts");
    const auto responses = static_cast<std::size_t>(length);
    const std::span<const double> all = std::span<const double>(state).first(state.size() - 1);
    if (flow_->responses)
      flow_->responses->restore(all.last(responses));
    else if (responses > 0)
      throw std::invalid_argument("it holds the bodies' responses, which the staircase does not measure");
    flow_->flow.restore(all.first(all.size() - responses - bodies));
    flow_->bodies->restore(all.subspan(all.size() - responses - bodies, bodies));
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(std::string("restart state: ") + e.what());
  }
}

}  // namespace cosim::fluid::program
