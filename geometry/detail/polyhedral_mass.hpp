#pragma once

#include <Eigen/Core>
#include <vector>

#include "geometry/triangle.hpp"

namespace cosim::geometry::detail {

struct PolyhedronMass {
  double volume;
  Eigen::Vector3d center;   // centre of mass in the input frame
  Eigen::Matrix3d inertia;  // about `center`, density 1
};

// Exact volume integrals of 1, x, y, z, x^2, ..., xy, ... over a closed outward-oriented
// triangle mesh by the divergence theorem: D. Eberly, "Polyhedral Mass Properties
// (Revisited)", Geometric Tools 2002 (a simplification of Mirtich 1996 for triangles).
// Integrated about the vertex mean so that a mesh far from the origin does not lose digits.
PolyhedronMass polyhedral_mass(const std::vector<Eigen::Vector3d>& vertices, const std::vector<Triangle>& triangles);

}  // namespace cosim::geometry::detail
