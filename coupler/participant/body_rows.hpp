#pragma once
// A body's row of the Poses and Forces arrays (protocol/message.hpp: kPoseWidth and
// kForceWidth values a body, in the scene's body order), typed: participants read and
// write the rows through these, never by index.

#include <Eigen/Geometry>

#include <cstddef>
#include <span>
#include <vector>

namespace cosim::participant {

struct PoseRow {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  // w x y z on the wire
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();
};

struct ForceRow {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();
};

// Row `body` of a Poses or Forces array (the caller checked the array's size).
PoseRow pose_row(std::span<const double> poses, std::size_t body);
ForceRow force_row(std::span<const double> forces, std::size_t body);
// Appends a row.
void append(std::vector<double>& poses, const PoseRow& row);
void append(std::vector<double>& forces, const ForceRow& row);

}  // namespace cosim::participant
