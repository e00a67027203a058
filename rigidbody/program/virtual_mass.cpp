#include "rigidbody/program/virtual_mass.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace cosim::program {

std::vector<dynamics::WindowWrench> VirtualMass::blend(double t0, std::span<const dynamics::BodyState> start,
                                                       std::span<const dynamics::BodyInertia> inertia,
                                                       const dynamics::BodyForces& body_forces,
                                                       std::span<const dynamics::WindowWrench> fluid) {
  const bool first = previous_.size() != start.size() || !(t0 > previous_time_);
  std::vector<dynamics::WindowWrench> out(fluid.begin(), fluid.end());
  for (std::size_t b = 0; b < out.size() && b < start.size(); ++b) {
    const dynamics::BodyInertia& body = inertia[b];
    if (body.is_fixed()) continue;
    const double w = body.density / (body.density + coefficient_ * fluid_density_);
    Eigen::Vector3d a = Eigen::Vector3d::Zero(), alpha = Eigen::Vector3d::Zero();
    if (!first) {
      a = (start[b].velocity - previous_[b].velocity) / (t0 - previous_time_);
      alpha = (start[b].angular_velocity - previous_[b].angular_velocity) / (t0 - previous_time_);
    }
    const Eigen::Vector3d force = (a - body_forces.acceleration(body)) / body.inverse_mass;
    const Eigen::Matrix3d r = start[b].orientation.toRotationMatrix();
    const Eigen::Vector3d torque = r * body.inertia_body * r.transpose() * alpha;
    for (dynamics::Wrench* x : {&out[b].start, &out[b].end}) {
      x->force = w * x->force + (1 - w) * force;
      x->torque = w * x->torque + (1 - w) * torque;
    }
  }
  previous_.assign(start.begin(), start.end());
  previous_time_ = t0;
  return out;
}

void VirtualMass::save(std::vector<double>& out, std::size_t bodies) const {
  const bool known = previous_.size() == bodies;
  out.push_back(known ? previous_time_ : std::numeric_limits<double>::quiet_NaN());
  for (std::size_t b = 0; b < bodies; ++b) {
    const dynamics::BodyState s = known ? previous_[b] : dynamics::BodyState{};
    out.insert(out.end(), s.velocity.data(), s.velocity.data() + 3);
    out.insert(out.end(), s.angular_velocity.data(), s.angular_velocity.data() + 3);
  }
}

std::size_t VirtualMass::load(std::span<const double> in, std::size_t bodies) {
  const std::size_t size = 1 + 6 * bodies;
  if (in.size() < size) throw std::runtime_error("restart state: too short for the virtual mass's velocities");
  previous_.clear();
  previous_time_ = 0;
  if (std::isnan(in[0])) return size;
  previous_time_ = in[0];
  previous_.resize(bodies);
  for (std::size_t b = 0; b < bodies; ++b) {
    previous_[b].velocity = Eigen::Vector3d(in.data() + 1 + 6 * b);
    previous_[b].angular_velocity = Eigen::Vector3d(in.data() + 4 + 6 * b);
  }
  return size;
}

}  // namespace cosim::program
