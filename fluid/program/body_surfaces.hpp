// The bodies' surfaces as point sets of the run file, so that ParaView shows the bodies
// with the flow: points about a cell apart on each surface (geometry::sample_surface; on a
// two-dimensional grid the section by the layer's midplane), kept in the body's frame and
// placed where the body is now.
#pragma once

#include <string>
#include <vector>

#include "coupler/field/field_frame.hpp"
#include "fluid/bodies/body_treatment.hpp"
#include "fluid/grid/grid.hpp"
#include "geometry/sampled_shapes.hpp"

namespace cosim::fluid::program {

// Body `body`'s surface points in its frame on a grid of `axes`, as BodySurfaces keeps them
// (`sampled` reuses a shape's sampling for the bodies that share it).
std::vector<Eigen::Vector3d> surface_points(const fluid::grid::Axes& axes, const fluid::bodies::RigidBody& body,
                                            geometry::SampledShapes& sampled);

class BodySurfaces {
 public:
  // `bodies` where they start, named as in the scene.
  BodySurfaces(const fluid::grid::Grid& grid, const fluid::bodies::BodyTreatment& bodies,
               std::vector<std::string> names);
  // One set per body, named after it, where `bodies` places it now.
  std::vector<field::PointSet> where(const fluid::bodies::BodyTreatment& bodies) const;

 private:
  std::vector<std::string> names_;
  std::vector<std::vector<Eigen::Vector3d>> points_;  // body frame
};

}  // namespace cosim::fluid::program
