#include "coupler/participant/poses_at.hpp"

#include <cmath>

#include "coupler/protocol/message.hpp"

namespace cosim::participant {

std::vector<double> poses_at(const Inputs& in, const Window& w, double s) {
  constexpr std::size_t width = protocol::kPoseWidth;
  const auto& end = in.poses_end.empty() ? in.poses_start : in.poses_end;
  std::vector<double> out(in.poses_start.size());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = lerp(in.poses_start[i], end[i], w, s);
  for (std::size_t b = 0; b < out.size() / width; ++b) {
    double* q = out.data() + width * b + 3;
    const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    for (int k = 0; k < 4; ++k) q[k] /= norm;
  }
  return out;
}

}  // namespace cosim::participant
