// A CSG shape as the scene writes it: one mapping with a single key naming what it is.
//
//   ball: {centre: [x, y, z], radius: r}
//   half_space: {point: [..], normal: [..]}          the solid behind the plane; normal outward
//   cylinder: {point: [..], axis: [..], radius: r}   infinite along the axis
//   capped_cylinder: {base: [..], top: [..], radius: r}
//   box: {centre: [..], half_extents: [..], orientation: [w, x, y, z]}   orientation optional
//   union: [shape, shape, ...]      intersection: [shape, ...]      difference: [a, b]
//   complement: shape
//   transform: {translate: [..], rotate: {axis: [..], angle: rad}, shape: shape}
//   lattice: {shape: shape, spacing: [..], count: [nx, ny, nz]}   the union of the shape
//                                          translated by (i, j, k) * spacing, i < nx, ...
//   balls: {file: path}     the union of the balls in a text file, one "x y z r" per line
//                           (# starts a comment); the path is relative to the scene file
//
// Errors name the file, line and key (scene::SceneError), for a balls file its line too.
#pragma once

#include "coupler/scene/reader.hpp"
#include "tracker/csg/expression.hpp"

namespace cosim::tracker::program {

// `folder`: where a relative file name (a balls file) is found, the scene's `folder`.
csg::Expression read_shape(const scene::Reader& shape, const std::filesystem::path& folder);

}  // namespace cosim::tracker::program
