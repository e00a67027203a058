#pragma once
// A body's row of the Poses and Forces arrays (protocol/message.hpp: kPoseWidth and
// kForceWidth values a body, in the scene's body order), typed: solvers get and give rows
// (solver.hpp), and the flat values appear only where rows are stored: in messages, run
// files and restart states.

#include <Eigen/Geometry>

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

// The rows of a Poses or Forces array's values, which the caller checked to be whole rows.
std::vector<PoseRow> pose_rows(std::span<const double> values);
std::vector<ForceRow> force_rows(std::span<const double> values);
// The array's values of these rows, row-major.
std::vector<double> values_of(std::span<const PoseRow> rows);
std::vector<double> values_of(std::span<const ForceRow> rows);

}  // namespace cosim::participant
