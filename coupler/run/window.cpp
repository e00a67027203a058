#include "coupler/run/window.hpp"

#include <algorithm>

#include "coupler/participant/robin.hpp"
#include "coupler/protocol/field_message.hpp"
#include "coupler/protocol/messages.hpp"
#include "coupler/run/failure.hpp"

namespace cosim::run {
namespace {

// The change relative to the larger of the data at the window's start and end: the window
// applies everything between the two, and a force that passes through zero in it (a body
// stopping) would otherwise be held to a tolerance its own solver's round-off exceeds.
double relative(const Eigen::VectorXd& change, const Eigen::VectorXd& start, const Eigen::VectorXd& end) {
  const double c = change.norm();
  return c == 0.0 ? 0.0 : c / std::max({start.norm(), end.norm(), 1e-300});
}

Eigen::VectorXd stack(const Exchange& e) {
  Eigen::VectorXd x(e.poses.size() + e.forces.size());
  x << e.poses, e.forces;
  return x;
}

Exchange unstack(const Eigen::VectorXd& x, Eigen::Index n_poses) {
  return {x.head(n_poses), x.tail(x.size() - n_poses), {}};
}

// The accelerator mixes iterates linearly, which shortens quaternions; participants are
// given rotations.
Exchange with_unit_quaternions(Exchange e) {
  for (Eigen::Index i = 0; i + kPoseSize <= e.poses.size(); i += kPoseSize) {
    auto q = e.poses.segment<4>(i + 3);
    if (q.norm() > 0) q.normalize();
  }
  return e;
}

// Each block divided by its norm, so poses in metres and forces in newtons weigh alike.
Eigen::VectorXd block_weights(const Exchange& e) {
  const auto weight = [](const Eigen::VectorXd& v) { return v.norm() > 0 ? 1.0 / v.norm() : 1.0; };
  Eigen::VectorXd w(e.poses.size() + e.forces.size());
  w << Eigen::VectorXd::Constant(e.poses.size(), weight(e.poses)),
      Eigen::VectorXd::Constant(e.forces.size(), weight(e.forces));
  return w;
}

// A body's velocity (linear, then angular) in a pose vector.
participant::Vector6d velocity_of(const Eigen::VectorXd& poses, Eigen::Index body) {
  return poses.segment<6>(kPoseSize * body + 7);
}

participant::ResponseRow response_of(const Eigen::VectorXd& responses, Eigen::Index body) {
  return participant::response_rows(
      {responses.data() + kResponseSize * body, static_cast<std::size_t>(kResponseSize)})[0];
}

participant::ForceRow force_of(const Eigen::VectorXd& forces, Eigen::Index body) {
  return {forces.segment<3>(kForceSize * body), forces.segment<3>(kForceSize * body + 3)};
}

// The Robin wrenches of a new window (participant/robin.hpp): each body keeping its velocity
// at the window's start, with the load the response says that brings.
Eigen::VectorXd next_window_wrenches(const Exchange& start) {
  Eigen::VectorXd out(start.forces.size());
  for (Eigen::Index b = 0; b < out.size() / kForceSize; ++b)
    out.segment<6>(kForceSize * b) =
        participant::robin_wrench(response_of(start.responses, b), velocity_of(start.poses, b));
  return out;
}

// The Robin wrenches of a repeated window: the loads `forces` of the motion from the start's
// velocities to those of `poses`, with the start's responses.
Eigen::VectorXd repeat_wrenches(const Exchange& start, const Eigen::VectorXd& forces, const Eigen::VectorXd& poses,
                                double length) {
  Eigen::VectorXd out(forces.size());
  for (Eigen::Index b = 0; b < out.size() / kForceSize; ++b)
    out.segment<6>(kForceSize * b) =
        participant::robin_wrench(response_of(start.responses, b), force_of(forces, b), velocity_of(start.poses, b),
                                  velocity_of(poses, b), length);
  return out;
}

}  // namespace

WindowRunner::WindowRunner(Peers& peers, Roles roles, const scene::Coupling& coupling)
    : peers_(peers),
      roles_(std::move(roles)),
      coupling_(coupling),
      accelerator_(coupling::make_accelerator(coupling.acceleration, coupling.relaxation)) {}

WindowResult WindowRunner::advance(std::uint64_t window, double t0, double t1, const Exchange& start,
                                   const FieldArrays& fields) {
  const Span s{window, t0, t1, in_window(window, t0, t1), fields};
  // With nobody on one side there is no loop to close: one pass is exact.
  const bool closed = !roles_.pose_providers.empty() && !roles_.force_providers.empty();
  switch (coupling_.scheme) {
    case scene::Scheme::SerialExplicit:
      return serial_explicit(s, start);
    case scene::Scheme::ParallelExplicit:
      return parallel_explicit(s, start);
    case scene::Scheme::SerialImplicit:
      return closed ? serial_implicit(s, start) : serial_explicit(s, start);
    case scene::Scheme::ParallelImplicit:
      return closed ? parallel_implicit(s, start) : parallel_explicit(s, start);
  }
  return {};
}

Exchange WindowRunner::call(const std::vector<std::string>& names, const Span& s, int iteration, const Exchange& start,
                            const Exchange& end, WindowResult& r) {
  std::map<std::string, protocol::Message> requests;
  for (const auto& name : names) {
    std::vector<protocol::Array> inputs;
    if (scene::has(roles_.needs.at(name), scene::Data::Poses)) {
      inputs.push_back(poses_array(start.poses));
      inputs.push_back(poses_array(end.poses));
    }
    if (scene::has(roles_.needs.at(name), scene::Data::Forces)) {
      inputs.push_back(forces_array(start.forces));
      inputs.push_back(forces_array(end.forces));
      if (end.responses.size() > 0) inputs.push_back(responses_array(end.responses));
    }
    if (const auto f = s.fields.find(name); f != s.fields.end()) {
      inputs.insert(inputs.end(), f->second.begin(), f->second.end());
      r.field_bytes[name] += static_cast<double>(protocol::payload_bytes(f->second));
    }
    requests.emplace(name, protocol::messages::advance(s.window, static_cast<std::uint32_t>(iteration), s.t0, s.t1,
                                                       std::move(inputs)));
  }
  const auto replies = peers_.exchange(std::move(requests), protocol::Type::Result, s.when);

  Exchange out = end;
  bool forces_returned = false;
  Eigen::VectorXd force_sum = Eigen::VectorXd::Zero(end.forces.size());
  Eigen::VectorXd response_sum;
  for (const auto& [name, m] : replies) {
    const Eigen::VectorXd stats = take(m, protocol::Tag::Stats, 2, s.when);
    r.substeps[name] += stats(0);
    r.wall_seconds[name] += stats(1);
    if (scene::has(roles_.provides.at(name), scene::Data::Poses))
      out.poses = take(m, protocol::Tag::Poses, end.poses.size(), s.when);
    if (scene::has(roles_.provides.at(name), scene::Data::Forces)) {
      force_sum += take(m, protocol::Tag::Forces, end.forces.size(), s.when);
      forces_returned = true;
      if (m.find(protocol::Tag::Responses) == nullptr) continue;
      const Eigen::Index size = end.forces.size() / kForceSize * kResponseSize;
      if (response_sum.size() == 0) response_sum = Eigen::VectorXd::Zero(size);
      response_sum += take(m, protocol::Tag::Responses, size, s.when);
    }
  }
  if (forces_returned) {
    out.forces = force_sum;
    out.responses = response_sum;
  }
  return out;
}

void WindowRunner::observe(const Span& s, int iteration, const Exchange& start, WindowResult& r) {
  if (!roles_.others.empty()) call(roles_.others, s, iteration, start, r.end, r);
}

// With response tensors the pose provider gets the Robin wrenches in place of the forces
// (participant/robin.hpp), and the responses they were formed with.
WindowResult WindowRunner::serial_explicit(const Span& s, const Exchange& start) {
  WindowResult r;
  r.iterations = 1;
  r.end = start;
  if (start.responses.size() > 0) r.end.forces = next_window_wrenches(start);
  if (!roles_.pose_providers.empty()) r.end = call(roles_.pose_providers, s, 1, start, r.end, r);
  if (!roles_.force_providers.empty()) r.end = call(roles_.force_providers, s, 1, start, r.end, r);
  observe(s, 1, start, r);
  return r;
}

// The parallel schemes hand the pose provider no response tensors: its forces were computed
// for poses held or guessed, not for the motion it made, which the tensors refer to.
WindowResult WindowRunner::parallel_explicit(const Span& s, const Exchange& start) {
  WindowResult r;
  r.iterations = 1;
  Exchange held = start;
  held.responses = {};
  r.end = call(roles_.all(), s, 1, held, held, r);
  return r;
}

bool WindowRunner::converged(double relative_change, const Eigen::VectorXd& force_change) const {
  return relative_change <= coupling_.tolerance || force_change.norm() <= coupling_.force_tolerance;
}

// With response tensors the iterations run on the Robin wrenches (participant/robin.hpp),
// formed with the responses of the window's start in every iteration: the pose provider's
// motion is then a fixed function of the wrench, and the force providers' loads, with the
// motion they were computed for, give the next wrench.
WindowResult WindowRunner::serial_implicit(const Span& s, const Exchange& start) {
  WindowResult r;
  accelerator_->new_window();
  const bool robin = start.responses.size() > 0;
  const Eigen::VectorXd first = robin ? next_window_wrenches(start) : start.forces;
  Eigen::VectorXd x = first;
  for (int it = 1; it <= coupling_.max_iterations; ++it) {
    const Exchange moved = call(roles_.pose_providers, s, it, start, {start.poses, x, start.responses}, r);
    r.end = call(roles_.force_providers, s, it, start, moved, r);
    observe(s, it, start, r);
    r.iterations = it;
    const Eigen::VectorXd y = robin ? repeat_wrenches(start, r.end.forces, r.end.poses, s.t1 - s.t0) : r.end.forces;
    r.residual = relative(y - x, first, y);
    if (converged(r.residual, y - x)) return r;
    x = accelerator_->next(x, y);
  }
  r.converged = false;
  return r;
}

WindowResult WindowRunner::parallel_implicit(const Span& s, const Exchange& start) {
  WindowResult r;
  accelerator_->new_window();
  const auto n_poses = start.poses.size();
  Eigen::VectorXd x = stack(start);
  Eigen::VectorXd weights;
  for (int it = 1; it <= coupling_.max_iterations; ++it) {
    const Exchange guess = with_unit_quaternions(unstack(x, n_poses));
    r.end = call(roles_.all(), s, it, start, guess, r);
    r.iterations = it;
    const double poses = relative(r.end.poses - guess.poses, start.poses, r.end.poses);
    const double forces = relative(r.end.forces - guess.forces, start.forces, r.end.forces);
    r.residual = std::max(poses, forces);
    if (poses <= coupling_.tolerance && converged(forces, r.end.forces - guess.forces)) return r;
    if (it == 1) weights = block_weights(r.end);
    const Eigen::VectorXd next = accelerator_->next(x.cwiseProduct(weights), stack(r.end).cwiseProduct(weights));
    x = next.cwiseQuotient(weights);
  }
  r.converged = false;
  return r;
}

}  // namespace cosim::run
