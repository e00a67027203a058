#include "rigidbody/program/virtual_mass.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace cosim::rigidbody::program {

std::vector<dynamics::WindowWrench> VirtualMass::blend(std::span<const dynamics::BodyInertia> inertia,
                                                       const dynamics::BodyForces& body_forces,
                                                       std::span<const dynamics::WindowWrench> fluid) {
  if (previous_.size() != fluid.size()) {
    previous_.assign(fluid.size(), {});
    for (std::size_t b = 0; b < fluid.size() && b < inertia.size(); ++b)
      if (!inertia[b].is_fixed()) previous_[b].force = -body_forces.acceleration(inertia[b]) / inertia[b].inverse_mass;
  }
  std::vector<dynamics::WindowWrench> out(fluid.begin(), fluid.end());
  for (std::size_t b = 0; b < out.size() && b < inertia.size(); ++b) {
    const dynamics::BodyInertia& body = inertia[b];
    if (body.is_fixed()) continue;
    const double w = body.density / (body.density + coefficient_ * fluid_density_);
    for (dynamics::Wrench* x : {&out[b].start, &out[b].end}) {
      x->force = w * x->force + (1 - w) * previous_[b].force;
      x->torque = w * x->torque + (1 - w) * previous_[b].torque;
    }
    // The fluid's wrenches are window means, held: start and end are equal.
    previous_[b] = out[b].end;
  }
  return out;
}

void VirtualMass::save(std::vector<double>& out, std::size_t bodies) const {
  const bool known = previous_.size() == bodies;
  out.push_back(known ? 1.0 : std::numeric_limits<double>::quiet_NaN());
  for (std::size_t b = 0; b < bodies; ++b) {
    const dynamics::Wrench x = known ? previous_[b] : dynamics::Wrench{};
    out.insert(out.end(), x.force.data(), x.force.data() + 3);
    out.insert(out.end(), x.torque.data(), x.torque.data() + 3);
  }
}

std::size_t VirtualMass::load(std::span<const double> in, std::size_t bodies) {
  const std::size_t size = 1 + 6 * bodies;
  if (in.size() < size) throw std::runtime_error("restart state: too short for the virtual mass's wrenches");
  previous_.clear();
  if (std::isnan(in[0])) return size;
  previous_.resize(bodies);
  for (std::size_t b = 0; b < bodies; ++b) {
    previous_[b].force = Eigen::Vector3d(in.data() + 1 + 6 * b);
    previous_[b].torque = Eigen::Vector3d(in.data() + 4 + 6 * b);
  }
  return size;
}

}  // namespace cosim::rigidbody::program
