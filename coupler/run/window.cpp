#include "coupler/run/window.hpp"

#include <algorithm>

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

}  // namespace

WindowRunner::WindowRunner(Peers& peers, Roles roles, const scene::Coupling& coupling)
    : peers_(peers),
      roles_(std::move(roles)),
      coupling_(coupling),
      accelerator_(coupling::make_accelerator(coupling.acceleration, coupling.relaxation)) {}

WindowResult WindowRunner::advance(std::uint64_t window, double t0, double t1,
                                   const Exchange& start, const FieldArrays& fields) {
  const Span s{window, t0, t1, in_window(window, t0, t1), fields};
  // With nobody on one side there is no loop to close: one pass is exact.
  const bool closed = !roles_.pose_providers.empty() && !roles_.force_providers.empty();
  switch (coupling_.scheme) {
    case scene::Scheme::SerialExplicit: return serial_explicit(s, start);
    case scene::Scheme::ParallelExplicit: return parallel_explicit(s, start);
    case scene::Scheme::SerialImplicit:
      return closed ? serial_implicit(s, start) : serial_explicit(s, start);
    case scene::Scheme::ParallelImplicit:
      return closed ? parallel_implicit(s, start) : parallel_explicit(s, start);
  }
  return {};
}

Exchange WindowRunner::call(const std::vector<std::string>& names, const Span& s, int iteration,
                            const Exchange& start, const Exchange& end, WindowResult& r) {
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

WindowResult WindowRunner::serial_explicit(const Span& s, const Exchange& start) {
  WindowResult r;
  r.iterations = 1;
  r.end = start;
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

WindowResult WindowRunner::serial_implicit(const Span& s, const Exchange& start) {
  WindowResult r;
  accelerator_->new_window();
  Eigen::VectorXd x = start.forces;
  for (int it = 1; it <= coupling_.max_iterations; ++it) {
    const Exchange moved =
        call(roles_.pose_providers, s, it, start, {start.poses, x, it == 1 ? start.responses : r.end.responses}, r);
    r.end = call(roles_.force_providers, s, it, start, moved, r);
    observe(s, it, start, r);
    r.iterations = it;
    r.residual = relative(r.end.forces - x, start.forces, r.end.forces);
    if (converged(r.residual, r.end.forces - x)) return r;
    // Forces that come with their response tensors go back unmixed: the pose provider moves
    // the bodies with the tensors against the motion those forces were computed for (its
    // previous iteration), which is the quasi-Newton step with the fluid's own Jacobian; a
    // mixture of forces would have no such motion.
    x = r.end.responses.size() > 0 ? r.end.forces : accelerator_->next(x, r.end.forces);
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
    const Eigen::VectorXd next =
        accelerator_->next(x.cwiseProduct(weights), stack(r.end).cwiseProduct(weights));
    x = next.cwiseQuotient(weights);
  }
  r.converged = false;
  return r;
}

}  // namespace cosim::run
