// How bodies move in a standalone fluid run, where no rigid-body program moves them:
// fixed, at constant linear and angular velocity, or oscillating sinusoidally (translating
// and/or turning about a fixed axis).
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "coupler/participant/body_rows.hpp"
#include "coupler/scene/reader.hpp"

namespace cosim::fluid::program {

struct Motion {
  enum class Kind { fixed, constant, sinusoidal };
  Kind kind = Kind::fixed;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // centre of mass at t = 0
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();          // constant
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();  // constant, world frame
  Eigen::Vector3d amplitude = Eigen::Vector3d::Zero();         // sinusoidal: x0 + A sin(2 pi f t)
  // Sinusoidal: the rotation vector theta0 sin(2 pi f t) (rad, world frame) applied to the
  // initial orientation, so the body swings about the fixed axis theta0 / |theta0|.
  Eigen::Vector3d angular_amplitude = Eigen::Vector3d::Zero();
  double frequency = 0;  // Hz
};

// The options' `motion` mapping: body name -> {type: fixed | constant | sinusoidal,
// amplitude: [m], angular_amplitude: [rad], frequency: Hz (sinusoidal only; either
// amplitude defaults to zero, not both)}. A body not listed is fixed if the scene
// says so, else moves at its scene velocity and angular velocity (constant). `start`
// holds each body's motion with position and orientation at t = 0 already set.
std::vector<Motion> read_motions(const scene::Scene& scene, const scene::Reader& options, std::vector<Motion> start);

// The bodies' poses at time t.
std::vector<participant::PoseRow> poses_at(const std::vector<Motion>& motions, double t);

}  // namespace cosim::fluid::program
