// What the broad phase sees of a body: its bounding sphere, or, for a wall, an infinite
// object that no grid could hold.
#pragma once

#include <cstdint>
#include <optional>
#include <utility>

#include <Eigen/Core>

namespace cosim::rigidbody::broadphase {

using Id = std::uint32_t;
// A candidate pair; always first < second.
using Pair = std::pair<Id, Id>;

// The solid half-space {x : normal . x <= offset}; the normal points out of the solid and
// need not have unit length.
struct HalfSpace {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  double offset = 0.0;
};

struct Object {
  Id id = 0;                                         // unique among the objects of one call
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // bounding-sphere centre
  double radius = 0.0;                               // bounding-sphere radius, >= 0
  // Never moves: two fixed objects are never a candidate pair.
  bool fixed = false;
  // A wall (plane, half-space): kept out of the grid, its centre and radius are ignored.
  // It is paired with every finite object, or with those near half_space when given.
  // Two infinite objects are never paired.
  bool infinite = false;
  std::optional<HalfSpace> half_space = std::nullopt;
};

}  // namespace cosim::rigidbody::broadphase
