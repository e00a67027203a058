#include "tracker/program/scene_obstacles.hpp"

#include <algorithm>
#include <set>

#include "coupler/scene/eigen.hpp"
#include "tracker/csg/shapes.hpp"
#include "tracker/program/csg_shape.hpp"
#include "tracker/program/scene_walls.hpp"

namespace cosim::tracker::program {
namespace {

// The body's own shape in its frame, as the rigid-body program and the fluid see it: a
// container is the solid outside its shape.
csg::Expression body_shape(const scene::Reader& r, const scene::Body& body) {
  using scene::ShapeType;
  const scene::Shape& s = body.shape;
  const auto solid = [&]() -> csg::Expression {
    switch (s.type) {
      case ShapeType::Sphere:
        return csg::ball(Eigen::Vector3d::Zero(), s.radius);
      case ShapeType::Box:
        return csg::box(Eigen::Vector3d::Zero(), scene::to_eigen(s.half_extents));
      case ShapeType::Cylinder:
        return csg::capped_cylinder({0, 0, -s.height / 2}, {0, 0, s.height / 2}, s.radius);
      default:
        r.fail("body", "body '" + body.name + "' has a shape CSG has no primitive for: give the obstacle a shape");
    }
  };
  return s.container ? ~solid() : solid();
}

int body_index(const scene::Reader& r, const scene::Scene& scene, const std::string& name) {
  const auto found =
      std::find_if(scene.bodies.begin(), scene.bodies.end(), [&](const scene::Body& b) { return b.name == name; });
  if (found == scene.bodies.end()) r.fail("body", "no body of that name in the scene's bodies");
  return static_cast<int>(found - scene.bodies.begin());
}

}  // namespace

Eigen::Isometry3d initial_pose(const scene::Body& body) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translate(scene::to_eigen(body.position));
  pose.rotate(scene::to_eigen(body.orientation).normalized());
  return pose;
}

SceneObstacles read_obstacles(const scene::Reader& options, const scene::Scene& scene) {
  SceneObstacles out;
  if (!options.has("obstacles")) return out;
  std::set<std::string> names;
  for (const scene::Reader& r : options.maps("obstacles")) {
    std::string name = r.string("name");
    if (name.empty() || !names.insert(name).second) r.fail("name", "expected a unique, non-empty name");
    const int body = r.has("body") ? body_index(r, scene, r.string("body")) : -1;
    csg::Tree shape(body >= 0 && !r.has("shape") ? body_shape(r, scene.bodies[static_cast<std::size_t>(body)])
                                                 : read_shape(r.map("shape"), scene.folder));
    const bool permeable = r.boolean("permeable", false);
    // A zone has no wall: `wall` on one stays unread, and finish() names it.
    tracking::BoundaryCondition wall;
    if (!permeable && r.has("wall")) wall = read_condition(r.map("wall"), false);
    r.finish();
    out.objects.push_back({std::move(name), std::move(shape), permeable, wall});
    out.body.push_back(body);
  }
  return out;
}

}  // namespace cosim::tracker::program
