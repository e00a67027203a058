// The data that crosses between participants in a window, and who sends and takes it.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "protocol/message.hpp"
#include "scene/scene.hpp"

namespace cosim::run {

inline constexpr int kPoseSize = 13;  // position, quaternion w x y z, velocity, angular velocity
inline constexpr int kForceSize = 6;  // force, torque

// Bodies in scene order.
struct Exchange {
  Eigen::VectorXd poses;
  Eigen::VectorXd forces;
};

struct Roles {
  std::vector<std::string> pose_providers;   // at most one (validated by the scene plan)
  std::vector<std::string> force_providers;  // their forces add up
  std::map<std::string, scene::DataSet> needs;
  std::map<std::string, scene::DataSet> provides;

  explicit Roles(const std::vector<scene::Participant>& started);
  std::vector<std::string> all() const;
};

// The scene's bodies as a pose vector.
Eigen::VectorXd initial_poses(const scene::Scene& scene);

protocol::Array poses_array(const Eigen::VectorXd& poses);
protocol::Array forces_array(const Eigen::VectorXd& forces);
Eigen::VectorXd vector_of(const protocol::Array& a);

}  // namespace cosim::run
