#include "coupler/run/exchange.hpp"

#include <fmt/format.h>

#include "coupler/run/failure.hpp"

namespace cosim::run {

Roles::Roles(const std::vector<scene::Participant>& started) {
  for (const auto& p : started) {
    if (scene::has(p.provides, scene::Data::Poses))
      pose_providers.push_back(p.name);
    else if (scene::has(p.provides, scene::Data::Forces))
      force_providers.push_back(p.name);
    else
      others.push_back(p.name);
    needs[p.name] = p.needs;
    provides[p.name] = p.provides;
  }
}

std::vector<std::string> Roles::all() const {
  std::vector<std::string> names;
  for (const auto& [name, n] : needs) names.push_back(name);
  return names;
}

Eigen::VectorXd initial_poses(const scene::Scene& scene) {
  Eigen::VectorXd p(kPoseSize * static_cast<Eigen::Index>(scene.bodies.size()));
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const auto& b = scene.bodies[i];
    double* row = p.data() + kPoseSize * i;
    std::copy(b.position.begin(), b.position.end(), row);
    std::copy(b.orientation.begin(), b.orientation.end(), row + 3);
    std::copy(b.velocity.begin(), b.velocity.end(), row + 7);
    std::copy(b.angular_velocity.begin(), b.angular_velocity.end(), row + 10);
  }
  return p;
}

namespace {

protocol::Array array_of(protocol::Tag tag, const Eigen::VectorXd& v, int cols) {
  return protocol::Array::of(tag, static_cast<std::uint32_t>(v.size() / cols), static_cast<std::uint32_t>(cols),
                             std::vector<double>(v.data(), v.data() + v.size()));
}

}  // namespace

protocol::Array poses_array(const Eigen::VectorXd& poses) { return array_of(protocol::Tag::Poses, poses, kPoseSize); }

protocol::Array forces_array(const Eigen::VectorXd& forces) {
  return array_of(protocol::Tag::Forces, forces, kForceSize);
}

protocol::Array responses_array(const Eigen::VectorXd& responses) {
  return array_of(protocol::Tag::Responses, responses, kResponseSize);
}

Eigen::VectorXd take(const protocol::Message& m, protocol::Tag tag, Eigen::Index size, const std::string& when) {
  const auto* a = m.find(tag);
  const auto* name = protocol::to_string(tag);
  if (a == nullptr)
    throw ParticipantFailure(m.header.participant,
                             fmt::format("sent {} without {}", protocol::to_string(m.header.type), name), when);
  if (static_cast<Eigen::Index>(a->values.size()) != size)
    throw ParticipantFailure(m.header.participant,
                             fmt::format("sent {} with {} values, expected {}", name, a->values.size(), size), when);
  return Eigen::Map<const Eigen::VectorXd>(a->values.data(), size);
}

}  // namespace cosim::run
