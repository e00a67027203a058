#pragma once
// Points spread evenly over a shape's surface, each standing for a share of its area: the
// Lagrangian markers of the fluid's immersed boundary and the bodies a run file shows.
//
// Method, for any shape with a signed distance: the surface is found where the distance
// changes sign along the edges of a lattice a quarter of the spacing wide (refined only in
// the lattice cells the surface passes near), each crossing standing for the area
// c^2 / |n|_1 the lattice lines meet it in (c the lattice width, n the normal). From these
// candidates random sequential adsorption picks points about `spacing` apart (a minimum
// distance of 0.8 spacing on a surface, 0.748 on a curve: near the saturation densities of
// random disks and of Renyi's parking problem, so that one point stands for about spacing^2
// of area, or spacing of length), and Lloyd iterations, each point moved to the candidate
// nearest the centroid of the candidates closest to it, even the spacing out. A point's
// area is that of the candidates closest to it. Deterministic: the same input gives the
// same points on every rank. The areas are exact on smooth surfaces to a fraction of a per
// cent; a lattice edge that clips a convex edge of the shape and leaves again is not seen,
// so shapes with edges come out short by about a lattice width times their edge length
// (a box ten spacings across: 1.4 %).
#include <vector>

#include "geometry/pose.hpp"
#include "geometry/shape.hpp"

namespace cosim::geometry {

struct SurfaceSample {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();    // on the surface, world frame
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // outward unit normal
  double area = 0;                                    // on a section: the length of curve
};

// The whole surface of `shape` at `pose`. Throws std::invalid_argument for a half-space or
// a spacing that is not positive.
std::vector<SurfaceSample> sample_surface(const Shape& shape, const Pose& pose, double spacing);

// The boundary curve of the shape's section by the plane x[axis] = at (a two-dimensional
// problem): points in that plane, normals within it, each standing for a length of curve.
// Empty when the plane misses the shape.
std::vector<SurfaceSample> sample_section(const Shape& shape, const Pose& pose, int axis, double at, double spacing);

// The dense points the sampling above picks from on a section's boundary curve: where the
// curve crosses a lattice of width spacing / 6 in the plane, each with the length of curve
// it stands for. Enough to measure distances within the plane to a small fraction of the
// lattice width, which the shape's own signed distance does not give when its nearest
// surface lies off the plane (the end caps of a cylinder as thick as the plane's layer).
std::vector<SurfaceSample> section_boundary(const Shape& shape, const Pose& pose, int axis, double at, double spacing);

}  // namespace cosim::geometry
