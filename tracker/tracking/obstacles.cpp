#include "tracker/tracking/obstacles.hpp"

#include "tracker/mesh/geometry.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace cosim::tracker::tracking {
namespace {

// A wall or zone must look the same from both sides of every periodic link (its images
// given), since a crossing re-evaluates the states on the far side: compared at each linked
// face's vertices and centre, skipping points within round-off of a primitive's surface.
void require_periodic(const mesh::Mesh& mesh, const Obstacle& object) {
  const auto clear = [&](const Vec3& x) {
    for (const csg::Primitive& p : object.shape.primitives())
      if (std::abs(p.indicator(x)) < 1e-9) return false;
    return true;
  };
  for (Index f = 0; f < mesh.face_count(); ++f) {
    const mesh::Face& face = mesh.faces[f];
    if (face.neighbour < 0 || face.shift == 0) continue;
    std::vector<Vec3> points{mesh::vertex_mean(mesh, f)};
    for (Index k = 0; k < mesh.vertex_count(f); ++k) points.push_back(mesh.face_vertex(f, k));
    for (const Vec3& x : points) {
      const Vec3 image = x + mesh.shifts[face.shift];
      if (!clear(x) || !clear(image) || object.shape.contains(x) == object.shape.contains(image)) continue;
      std::ostringstream where;
      where << x.transpose() << " and its periodic image " << image.transpose();
      throw std::invalid_argument("obstacle '" + object.name + "' differs at " + where.str() +
                                  ": across a periodic link, give the shape's images on both sides");
    }
  }
}

}  // namespace

void ObstacleTally::add(const ObstacleTally& other) {
  SurfaceTally::add(other);
  entered += other.entered;
  left += other.left;
  released += other.released;
  overrun += other.overrun;
  angular_impulse += other.angular_impulse;
}

Obstacles::Obstacles(const mesh::Mesh& tracking, std::vector<Obstacle> objects)
    : Obstacles(tracking, std::move(objects), tracking, {}) {}

Obstacles::Obstacles(const mesh::Mesh& tracking, std::vector<Obstacle> objects, const mesh::Mesh& bounding,
                     std::vector<Index> bounding_cell)
    : bounding_(&bounding), objects_(std::move(objects)), bounding_cell_(std::move(bounding_cell)) {
  if (!bounding_cell_.empty() && static_cast<Index>(bounding_cell_.size()) != tracking.cell_count())
    throw std::invalid_argument(tracking.source + ": " + std::to_string(bounding_cell_.size()) +
                                " bounding cells given for " + std::to_string(tracking.cell_count()) + " cells");
  for (const Obstacle& object : objects_) {
    if (!object.permeable && object.wall.kind == BoundaryKind::periodic)
      throw std::invalid_argument("obstacle '" + object.name + "': a wall cannot be periodic");
    if (!object.permeable && re_emits(object.wall) && !(object.wall.temperature > 0.0))
      throw std::invalid_argument("obstacle '" + object.name + "': a re-emitting wall needs a positive temperature");
    if (!object.permeable && refuses_velocity(object.wall))
      throw std::invalid_argument("obstacle '" + object.name + "': only diffuse and maxwell walls take a velocity");
    require_periodic(tracking, object);
    emits_ = emits_ || (!object.permeable && re_emits(object.wall));
    cells_.emplace_back(bounding, object.shape);
    poses_.push_back(Eigen::Isometry3d::Identity());
    motions_.emplace_back();
  }
  find_active();
}

Obstacles Obstacles::on(const mesh::Mesh& tracking) const {
  // The objects were checked when first registered: the shapes as they are placed now.
  Obstacles moved;
  moved.bounding_ = &tracking;
  moved.objects_ = objects_;
  moved.poses_ = poses_;
  moved.motions_ = motions_;
  moved.emits_ = emits_;
  for (const Obstacle& object : objects_) moved.cells_.emplace_back(tracking, object.shape);
  moved.find_active();
  return moved;
}

void Obstacles::find_active() {
  active_first_.assign(1, 0);
  active_.clear();
  for (Index b = 0; b < bounding_->cell_count(); ++b) {
    for (int o = 0; o < count(); ++o)
      if (!cells_[static_cast<std::size_t>(o)].primitives(b).empty()) active_.push_back(o);
    active_first_.push_back(static_cast<Index>(active_.size()));
  }
}

void ObstacleTally::exchange(const Vec3& x, const Vec3& origin, const Vec3& before, const Vec3& after) {
  SurfaceTally::exchange(before, after);
  angular_impulse += (x - origin).cross(before - after);
}

void Obstacles::classify(Index cell, const Vec3& x, std::span<csg::State> states) const {
  const Index b = bounding_cell(cell);
  for (std::size_t o = 0; o < cells_.size(); ++o) states[o] = cells_[o].classify(b, x);  // 0 where constant
}

bool Obstacles::inside_wall(Index cell, std::span<const csg::State> states) const {
  const Index b = bounding_cell(cell);
  for (std::size_t o = 0; o < cells_.size(); ++o)
    if (!objects_[o].permeable && cells_[o].tree(b).evaluate(states[o])) return true;
  return false;
}

void Obstacles::transfer(Index from, Index to, const Vec3& x, bool shifted, std::span<csg::State> states) const {
  const Index a = bounding_cell(from), b = bounding_cell(to);
  if (a == b && !shifted) return;
  for (const int o : active(b)) states[o] = shifted ? cells_[o].classify(b, x) : cells_[o].transfer(states[o], a, b, x);
}

}  // namespace cosim::tracker::tracking
