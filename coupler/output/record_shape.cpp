#include "coupler/output/record_shape.hpp"

#include <algorithm>

#include "coupler/output/h5_handle.hpp"

namespace cosim::output {

void check_body_rows(const std::string& what, const std::vector<double>& poses, const std::vector<double>& forces,
                     std::size_t bodies) {
  if (poses.size() != bodies * kPoseWidth || forces.size() != bodies * kForceWidth) {
    throw ObjectError(what + ": " + std::to_string(poses.size()) + " pose and " + std::to_string(forces.size()) +
                      " force values for " + std::to_string(bodies) + " bodies (" + std::to_string(kPoseWidth) +
                      " and " + std::to_string(kForceWidth) + " each)");
  }
}

template <class V>
void check_participants(const std::string& what, const std::map<std::string, V>& values,
                        const std::vector<std::string>& participants) {
  for (const auto& entry : values) {
    if (std::find(participants.begin(), participants.end(), entry.first) == participants.end()) {
      throw ObjectError(what + ": unknown participant '" + entry.first + "'");
    }
  }
}

template void check_participants(const std::string&, const std::map<std::string, double>&,
                                 const std::vector<std::string>&);
template void check_participants(const std::string&, const std::map<std::string, std::vector<double>>&,
                                 const std::vector<std::string>&);

}  // namespace cosim::output
