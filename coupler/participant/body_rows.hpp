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

// How a body's force changes with its motion, as the fluid that sends the force measured it
// (protocol::kResponseWidth values: added_mass and added_damping row-major, then hold):
// over the next window the mean force and torque are hold - added_mass [a; alpha] -
// added_damping ([v; omega] - [v0; omega0]) for a body whose acceleration a, alpha and mean
// velocity v, omega differ from keeping the velocity v0, omega0 it has at the window's start;
// `hold` is the load of that window if it does keep it. World frame, torques about the
// centre of mass.
struct ResponseRow {
  Eigen::Matrix<double, 6, 6> added_mass = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 6> added_damping = Eigen::Matrix<double, 6, 6>::Zero();
  ForceRow hold;
};

// The rows of a Poses or Forces array's values, which the caller checked to be whole rows.
std::vector<PoseRow> pose_rows(std::span<const double> values);
std::vector<ForceRow> force_rows(std::span<const double> values);
std::vector<ResponseRow> response_rows(std::span<const double> values);
// The array's values of these rows, row-major.
std::vector<double> values_of(std::span<const PoseRow> rows);
std::vector<double> values_of(std::span<const ForceRow> rows);
std::vector<double> values_of(std::span<const ResponseRow> rows);

}  // namespace cosim::participant
