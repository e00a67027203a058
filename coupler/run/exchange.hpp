// The data that crosses between participants in a window, and who sends and takes it.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "coupler/protocol/message.hpp"
#include "coupler/scene/scene.hpp"

namespace cosim::run {

inline constexpr int kPoseSize = protocol::kPoseWidth;
inline constexpr int kForceSize = protocol::kForceWidth;
inline constexpr int kResponseSize = protocol::kResponseWidth;

// Bodies in scene order. The response tensors travel with the forces they describe, summed
// over the providers that send them; empty when none does.
struct Exchange {
  Eigen::VectorXd poses;
  Eigen::VectorXd forces;
  Eigen::VectorXd responses;
};

struct Roles {
  std::vector<std::string> pose_providers;   // at most one (validated by the scene plan)
  std::vector<std::string> force_providers;  // their forces add up
  std::vector<std::string> others;           // provide neither: advanced after the rest
  std::map<std::string, scene::DataSet> needs;
  std::map<std::string, scene::DataSet> provides;

  explicit Roles(const std::vector<scene::Participant>& started);
  std::vector<std::string> all() const;
};

// The scene's bodies as a pose vector.
Eigen::VectorXd initial_poses(const scene::Scene& scene);

protocol::Array poses_array(const Eigen::VectorXd& poses);
protocol::Array forces_array(const Eigen::VectorXd& forces);
protocol::Array responses_array(const Eigen::VectorXd& responses);
// The `tag` array of a participant's message, which must hold exactly `size` values;
// anything else is that participant's failure.
Eigen::VectorXd take(const protocol::Message& m, protocol::Tag tag, Eigen::Index size, const std::string& when);

}  // namespace cosim::run
