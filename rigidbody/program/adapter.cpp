#include "rigidbody/program/adapter.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <spdlog/spdlog.h>

#include "coupler/participant/body_rows.hpp"
#include "coupler/protocol/message.hpp"
#include "rigidbody/program/scene_world.hpp"

namespace cosim::rigidbody::program {
namespace {

// The forces the fluid and the tracker send are the window's means (impulse over length),
// so each acts constant over its window: the newest one the scheme has, the end value.
// Empty forces: nobody sends any in this run, so the bodies feel only their own effects.
// The world's bodies after the scene's (the walls) get none.
std::vector<dynamics::WindowWrench> wrenches(const participant::Inputs& in, std::size_t bodies,
                                             std::size_t world_size) {
  const auto& mean = in.forces_end.empty() ? in.forces_start : in.forces_end;
  if (mean.empty()) return {};
  if (mean.size() != bodies)
    throw std::runtime_error("forces for " + std::to_string(mean.size()) + " bodies, the scene has " +
                             std::to_string(bodies));
  std::vector<dynamics::WindowWrench> out;
  for (const participant::ForceRow& f : mean) out.push_back({{f.force, f.torque}, {f.force, f.torque}});
  out.resize(world_size);
  return out;
}

dynamics::BodyState state_of(const participant::PoseRow& row) {
  dynamics::BodyState s;
  s.position = row.position;
  s.orientation = row.orientation;
  s.velocity = row.velocity;
  s.angular_velocity = row.angular_velocity;
  return s;
}

}  // namespace

participant::Outputs RigidSolver::initialise(const scene::Scene& scene, const std::string&,
                                             const std::vector<participant::PoseRow>&,
                                             const std::vector<double>& state) {
  // The scene gives the initial poses (with each mesh's centre-of-mass shift), so the
  // coupler's are not needed; a resumed run brings its own state.
  scene_ = scene;
  const ProgramOptions options = program_options(scene_);
  world_ = make_world(scene_, options);
  virtual_mass_ = VirtualMass(options.virtual_mass, options.settings.body_forces.fluid_density);
  if (!state.empty()) restore(state);
  return {poses(), {}, 0};
}

participant::Outputs RigidSolver::advance(const participant::Window& w, const participant::Inputs& in) {
  auto external = wrenches(in, scene_.bodies.size(), world_->size());
  std::vector<dynamics::AddedInertia> added;
  if (!in.responses.empty()) {
    // The forces are the coupler's Robin wrenches; the bodies carry the responses.
    if (virtual_mass_.active() && !warned_virtual_mass_) {
      spdlog::warn(
          "participants.rigidbody.options.virtual_mass is ignored: the fluid sends its response tensors, "
          "and the bodies move with those");
      warned_virtual_mass_ = true;
    }
    if (in.responses.size() != scene_.bodies.size())
      throw std::runtime_error("responses for " + std::to_string(in.responses.size()) + " bodies, the scene has " +
                               std::to_string(scene_.bodies.size()));
    added = added_inertia(in.responses);
    added.resize(world_->size());
  } else if (virtual_mass_.active() && !external.empty()) {
    external = virtual_mass_.blend(world_->inertias(), world_->settings().body_forces, external);
  }
  world_->set_time(w.t0);
  const world::StepReport report = world_->advance(w.t1 - w.t0, external, added);
  for (const std::string& warning : report.warnings) spdlog::warn("{}", warning);
  substeps_ += report.substeps;
  stage_seconds_ += report.seconds;
  return {poses(), {}, static_cast<double>(report.substeps)};
}

std::vector<double> RigidSolver::state() const {
  std::vector<double> s{world_->time()};
  const std::vector<double> p = participant::values_of(poses());
  s.insert(s.end(), p.begin(), p.end());
  if (virtual_mass_.active()) virtual_mass_.save(s, world_->size());
  world_->contact_memory().save(s);
  return s;
}

void RigidSolver::restore(const std::vector<double>& state) {
  const std::size_t bodies = scene_.bodies.size();
  std::size_t fixed_part = 1 + protocol::kPoseWidth * bodies;
  if (state.size() < fixed_part)
    throw std::runtime_error("restart state has " + std::to_string(state.size()) + " values, expected at least " +
                             std::to_string(fixed_part));
  if (virtual_mass_.active()) fixed_part += virtual_mass_.load(std::span(state).subspan(fixed_part), world_->size());
  try {
    world_->contact_memory().load(std::span(state).subspan(fixed_part));
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(std::string("restart state: ") + e.what());
  }
  // The world itself is kept: everything else in it is rebuilt every substep.
  world_->set_time(state[0]);
  const std::vector<participant::PoseRow> poses =
      participant::pose_rows(std::span(state).subspan(1, protocol::kPoseWidth * bodies));
  for (std::size_t b = 0; b < bodies; ++b) world_->states()[b] = state_of(poses[b]);
}

std::vector<participant::PoseRow> RigidSolver::poses() const {
  const std::size_t bodies = scene_.bodies.size();
  std::vector<participant::PoseRow> out;
  for (std::size_t b = 0; b < bodies; ++b) {
    const dynamics::BodyState& s = world_->states()[b];
    out.push_back({s.position, s.orientation, s.velocity, s.angular_velocity});
  }
  return out;
}

}  // namespace cosim::rigidbody::program
