#pragma once
// Surface samples (surface_sampling.hpp) of shapes in their body frames, made once per
// shape and spacing: a bed of a thousand equal spheres samples one sphere (a sampling costs
// about 27 ms for a sphere six cells across, which the fluid program does twice per body:
// markers and output points; bench/particulate's start column).
#include <tuple>
#include <vector>

#include "geometry/pose.hpp"
#include "geometry/shape.hpp"
#include "geometry/surface_sampling.hpp"

namespace cosim::geometry {

class SampledShapes {
 public:
  // The samples of `shape` in its body frame, `spacing` apart (within 1e-9 of it).
  const std::vector<SurfaceSample>& body_frame(const Shape& shape, double spacing);
  // The same, placed at `pose` (world frame).
  std::vector<SurfaceSample> at(const Shape& shape, const Pose& pose, double spacing);

 private:
  std::vector<std::tuple<Shape, double, std::vector<SurfaceSample>>> made_;
};

// Whether two shapes are the same: equal parameters, or hulls and meshes that share their
// data (copies of one).
bool same_shape(const Shape& a, const Shape& b);

}  // namespace cosim::geometry
