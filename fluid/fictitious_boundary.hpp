#pragma once
// The fictitious boundary method: bodies of any shape on the fixed fluid grid. Per body
// the indicator alpha at the velocity faces (faces with alpha >= 1/2 get the rigid
// velocity U + omega x (x - x_c), imposed in the viscous solve and kept by the projection;
// the force integral uses the same faces) and at the cell centres (the body's volume
// fraction per cell). Everything is rebuilt from the shapes
// and poses whenever a body moves, testing only the points in its bounding box.
//
//   FictitiousBoundary fbm(grid, {.subsamples = 4});
//   const std::size_t sphere = fbm.add({geometry::Sphere(0.1), pose});
//   flow.impose(&fbm.imposed_faces());
//   flow.step();  fbm.loads(flow)[sphere].force;  fbm.move(sphere, pose, velocity, omega);
#include <vector>

#include "fluid/fbm_indicator.hpp"
#include "fluid/fbm_load.hpp"
#include "fluid/imposed_faces.hpp"
#include "fluid/navier_stokes.hpp"
#include "fluid/rigid_body.hpp"

namespace cosim::fluid {

// The offset grows the body at the velocity faces only (what is imposed and what the
// force integral sees); the cell-centre fractions stay the body's own volume.
using FbmOptions = IndicatorOptions;

class FictitiousBoundary {
 public:
  // grid must outlive this object.
  explicit FictitiousBoundary(const Grid& grid, FbmOptions options = {});

  std::size_t add(RigidBody body);  // returns the body's index
  void move(std::size_t body, const geometry::Pose& pose, const Eigen::Vector3d& velocity,
            const Eigen::Vector3d& angular_velocity);
  const RigidBody& body(std::size_t i) const { return bodies_.at(i).body; }
  std::size_t size() const { return bodies_.size(); }

  // The faces inside bodies with their rigid velocities (for NavierStokes::impose).
  const ImposedFaces& imposed_faces() const { return imposed_; }
  // Force and torque (about the centre of mass) on every body from the flow's current
  // state. Collective.
  std::vector<HydrodynamicLoad> loads(const NavierStokes& flow) const;
  // sum of alpha times cell volume over the grid: the body's volume as the grid sees it.
  // Collective.
  double grid_volume(std::size_t i) const;
  // Body i's alpha at this rank's owned cell centres (zero outside its patch).
  const IndicatorPatch& cell_indicator(std::size_t i) const;
  // Grid points tested against body i's shape on this rank at its last move (faces of the
  // three components and cell centres).
  std::size_t points_tested(std::size_t i) const;

 private:
  struct Entry {
    RigidBody body;
    std::vector<IndicatorPatch> patches;  // velocity components 0..2, then cell centres
  };
  void build(Entry& e) const;
  void collect_imposed_faces();

  const Grid& grid_;
  FbmOptions options_;
  std::vector<Entry> bodies_;
  ImposedFaces imposed_;
};

}  // namespace cosim::fluid
