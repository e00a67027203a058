#include "geometry/queries.hpp"

#include <stdexcept>
#include <string>
#include <type_traits>

namespace cosim::geometry {
namespace {

template <class S>
concept Hinted = requires(const S& s, const Eigen::Vector3d& p, std::uint32_t& hint) {
  s.closest(p, hint);
};

// The queries of one shape type, carrying the mesh search hint from one point to the next.
template <class S>
class Querier {
 public:
  explicit Querier(const S& shape) : shape_(shape) {}

  double distance(const Eigen::Vector3d& p) {
    if constexpr (Hinted<S>)
      return shape_.closest(p, hint_).distance;
    else
      return shape_.signed_distance(p);
  }
  SurfacePoint closest(const Eigen::Vector3d& p) {
    if constexpr (Hinted<S>)
      return shape_.closest(p, hint_);
    else
      return shape_.closest(p);
  }
  // A mesh knows its side only through the distance search, which the hint speeds up.
  bool contains(const Eigen::Vector3d& p) {
    if constexpr (std::is_same_v<S, TriangleMesh>)
      return distance(p) <= 0.0;
    else
      return shape_.contains(p);
  }

 private:
  const S& shape_;
  std::uint32_t hint_ = 0;
};

template <class F>
auto query(const Shape& shape, F f) {
  return std::visit([&](const auto& s) { return f(Querier(s)); }, shape);
}

// The pose as a matrix, made once per call; single and batch queries go through it alike,
// so they round alike and give identical answers.
struct Frame {
  explicit Frame(const Pose& pose) : r(pose.rotation()), x(pose.position()) {}
  Eigen::Vector3d to_body(const Eigen::Vector3d& p) const { return r.transpose() * (p - x); }
  SurfacePoint to_world(const SurfacePoint& s) const { return {s.distance, r * s.point + x, r * s.normal}; }
  Eigen::Matrix3d r;
  Eigen::Vector3d x;
};

// out[i] = answer(querier, body-frame point i) for world points point_at(0..n-1); the shape
// is dispatched once for the whole batch.
template <class PointAt, class Out, class Answer>
void batch(const Shape& shape, const Pose& pose, std::size_t n, PointAt point_at, Out out, Answer answer) {
  if (out.size() != n)
    throw std::invalid_argument("batch query: " + std::to_string(n) + " points but room for " +
                                std::to_string(out.size()) + " answers");
  const Frame frame(pose);
  std::visit(
      [&](const auto& s) {
        Querier q(s);
        for (std::size_t i = 0; i < n; ++i) out[i] = answer(q, frame.to_body(point_at(i)));
      },
      shape);
}

auto distance_of = [](auto& q, const Eigen::Vector3d& p) { return q.distance(p); };
auto inside_of = [](auto& q, const Eigen::Vector3d& p) { return static_cast<std::uint8_t>(q.contains(p)); };

}  // namespace

double signed_distance(const Shape& shape, const Eigen::Vector3d& p) {
  return query(shape, [&](auto q) { return q.distance(p); });
}

SurfacePoint closest_point(const Shape& shape, const Eigen::Vector3d& p) {
  return query(shape, [&](auto q) { return q.closest(p); });
}

bool contains(const Shape& shape, const Eigen::Vector3d& p) {
  return query(shape, [&](auto q) { return q.contains(p); });
}

double signed_distance(const Shape& shape, const Pose& pose, const Eigen::Vector3d& p) {
  return signed_distance(shape, Frame(pose).to_body(p));
}

SurfacePoint closest_point(const Shape& shape, const Pose& pose, const Eigen::Vector3d& p) {
  const Frame frame(pose);
  return frame.to_world(closest_point(shape, frame.to_body(p)));
}

bool contains(const Shape& shape, const Pose& pose, const Eigen::Vector3d& p) {
  return contains(shape, Frame(pose).to_body(p));
}

void signed_distances(const Shape& shape, const Pose& pose, std::span<const Eigen::Vector3d> points,
                      std::span<double> out) {
  batch(
      shape, pose, points.size(), [&](std::size_t i) { return points[i]; }, out, distance_of);
}

void closest_points(const Shape& shape, const Pose& pose, std::span<const Eigen::Vector3d> points,
                    std::span<SurfacePoint> out) {
  batch(
      shape, pose, points.size(), [&](std::size_t i) { return points[i]; }, out,
      [frame = Frame(pose)](auto& q, const Eigen::Vector3d& p) { return frame.to_world(q.closest(p)); });
}

void contains(const Shape& shape, const Pose& pose, std::span<const Eigen::Vector3d> points,
              std::span<std::uint8_t> out) {
  batch(
      shape, pose, points.size(), [&](std::size_t i) { return points[i]; }, out, inside_of);
}

void signed_distances(const Shape& shape, const Pose& pose, const GridSpec& grid, std::span<double> out) {
  batch(
      shape, pose, grid.size(), [&](std::size_t i) { return grid.node(i); }, out, distance_of);
}

void closest_points(const Shape& shape, const Pose& pose, const GridSpec& grid, std::span<SurfacePoint> out) {
  batch(
      shape, pose, grid.size(), [&](std::size_t i) { return grid.node(i); }, out,
      [frame = Frame(pose)](auto& q, const Eigen::Vector3d& p) { return frame.to_world(q.closest(p)); });
}

}  // namespace cosim::geometry
