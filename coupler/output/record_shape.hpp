// The shape every WindowRecord and Checkpoint must have for the run's bodies and
// participants, checked before anything is written so a bad one changes nothing.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace cosim::output {

constexpr std::size_t kPoseWidth = 13;      // position, quaternion w x y z, velocity, omega
constexpr std::size_t kForceWidth = 6;      // force, torque
constexpr std::size_t kResponseWidth = 78;  // added mass, added damping (6 x 6 each), hold (6)

// Throws ObjectError starting with `what` unless poses/forces hold one row per body.
void check_body_rows(const std::string& what, const std::vector<double>& poses, const std::vector<double>& forces,
                     std::size_t bodies);
// Throws ObjectError starting with `what` if `values` names a participant the run lacks.
template <class V>
void check_participants(const std::string& what, const std::map<std::string, V>& values,
                        const std::vector<std::string>& participants);

}  // namespace cosim::output
