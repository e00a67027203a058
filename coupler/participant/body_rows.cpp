#include "coupler/participant/body_rows.hpp"

#include "coupler/protocol/message.hpp"

namespace cosim::participant {
namespace {

PoseRow pose_at(const double* v) {
  return {{v[0], v[1], v[2]}, Eigen::Quaterniond(v[3], v[4], v[5], v[6]), {v[7], v[8], v[9]}, {v[10], v[11], v[12]}};
}

ForceRow force_at(const double* f) { return {{f[0], f[1], f[2]}, {f[3], f[4], f[5]}}; }

ResponseRow response_at(const double* r) {
  using RowMajor = Eigen::Matrix<double, 6, 6, Eigen::RowMajor>;
  return {Eigen::Map<const RowMajor>(r), Eigen::Map<const RowMajor>(r + 36), force_at(r + 72)};
}

void append(std::vector<double>& poses, const PoseRow& r) {
  const Eigen::Quaterniond& q = r.orientation;
  poses.insert(poses.end(), {r.position.x(), r.position.y(), r.position.z(), q.w(), q.x(), q.y(), q.z(), r.velocity.x(),
                             r.velocity.y(), r.velocity.z(), r.angular_velocity.x(), r.angular_velocity.y(),
                             r.angular_velocity.z()});
}

void append(std::vector<double>& forces, const ForceRow& r) {
  forces.insert(forces.end(), {r.force.x(), r.force.y(), r.force.z(), r.torque.x(), r.torque.y(), r.torque.z()});
}

void append(std::vector<double>& responses, const ResponseRow& r) {
  for (const auto* m : {&r.added_mass, &r.added_damping})
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j) responses.push_back((*m)(i, j));
  append(responses, r.hold);
}

template <class Row>
std::vector<Row> decoded(std::span<const double> values, std::size_t width, Row (*row_at)(const double*)) {
  std::vector<Row> out;
  out.reserve(values.size() / width);
  for (std::size_t at = 0; at + width <= values.size(); at += width) out.push_back(row_at(values.data() + at));
  return out;
}

template <class Row>
std::vector<double> encoded(std::span<const Row> rows, std::size_t width) {
  std::vector<double> out;
  out.reserve(width * rows.size());
  for (const Row& row : rows) append(out, row);
  return out;
}

}  // namespace

std::vector<PoseRow> pose_rows(std::span<const double> values) {
  return decoded(values, protocol::kPoseWidth, pose_at);
}

std::vector<ForceRow> force_rows(std::span<const double> values) {
  return decoded(values, protocol::kForceWidth, force_at);
}

std::vector<ResponseRow> response_rows(std::span<const double> values) {
  return decoded(values, protocol::kResponseWidth, response_at);
}

std::vector<double> values_of(std::span<const PoseRow> rows) { return encoded(rows, protocol::kPoseWidth); }

std::vector<double> values_of(std::span<const ForceRow> rows) { return encoded(rows, protocol::kForceWidth); }

std::vector<double> values_of(std::span<const ResponseRow> rows) { return encoded(rows, protocol::kResponseWidth); }

}  // namespace cosim::participant
