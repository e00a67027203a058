#include "fluid/program/body_surfaces.hpp"

#include <algorithm>
#include <limits>

namespace cosim::fluid::program {

std::vector<Eigen::Vector3d> surface_points(const fluid::grid::Axes& axes, const fluid::bodies::RigidBody& body,
                                            geometry::SampledShapes& sampled) {
  const auto axis = [&](int d) -> const fluid::grid::Axis& { return axes[static_cast<std::size_t>(d)]; };
  int flat = -1;
  for (int d = 0; d < 3; ++d)
    if (axis(d).degenerate()) flat = d;
  double h = std::numeric_limits<double>::infinity();
  for (int d = 0; d < 3; ++d)
    if (d != flat) h = std::min(h, axis(d).width(axis(d).cell_at(body.pose.position()[d])));
  std::vector<Eigen::Vector3d> frame;
  if (flat < 0)
    for (const geometry::SurfaceSample& s : sampled.body_frame(body.shape, h)) frame.push_back(s.point);
  else
    for (const geometry::SurfaceSample& s :
         geometry::sample_section(body.shape, body.pose, flat, axis(flat).centre(0), h))
      frame.push_back(body.pose.to_body(s.point));
  return frame;
}

BodySurfaces::BodySurfaces(const fluid::grid::Grid& grid, const fluid::bodies::BodyTreatment& bodies,
                           std::vector<std::string> names)
    : names_(std::move(names)) {
  geometry::SampledShapes sampled;
  for (std::size_t b = 0; b < bodies.size(); ++b)
    points_.push_back(surface_points(grid.axes(), bodies.body(b), sampled));
}

std::vector<field::PointSet> BodySurfaces::where(const fluid::bodies::BodyTreatment& bodies) const {
  std::vector<field::PointSet> out;
  for (std::size_t b = 0; b < points_.size(); ++b) {
    field::PointSet set{names_.at(b), {}};
    for (const Eigen::Vector3d& p : points_[b]) {
      const Eigen::Vector3d x = bodies.body(b).pose.to_world(p);
      set.points.insert(set.points.end(), {x[0], x[1], x[2]});
    }
    out.push_back(std::move(set));
  }
  return out;
}

}  // namespace cosim::fluid::program
