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
//   flow.step(fbm.for_step());  fbm.loads(flow)[sphere].force;  fbm.move(sphere, pose, velocity, omega);
#include <vector>

#include "fluid/bodies/body_treatment.hpp"
#include "fluid/bodies/imposed_faces.hpp"
#include "fluid/bodies/rigid_body.hpp"
#include "fluid/navier_stokes/navier_stokes.hpp"
#include "fluid/staircase/fbm_indicator.hpp"
#include "fluid/staircase/fbm_load.hpp"

namespace cosim::fluid::staircase {

// The offset grows the body at the velocity faces only (what is imposed and what the
// force integral sees); the cell-centre fractions stay the body's own volume.
using FbmOptions = IndicatorOptions;

class FictitiousBoundary final : public bodies::BodyTreatment {
 public:
  // grid must outlive this object.
  explicit FictitiousBoundary(const grid::Grid& grid, FbmOptions options = {});

  std::size_t add(bodies::RigidBody body) override;
  void move(std::size_t body, const geometry::Pose& pose, const Eigen::Vector3d& velocity,
            const Eigen::Vector3d& angular_velocity) override;
  const bodies::RigidBody& body(std::size_t i) const override { return bodies_.at(i).body; }
  std::size_t size() const override { return bodies_.size(); }

  bodies::StepBodies for_step() override { return {.imposed = &imposed_}; }
  // The faces inside bodies with their rigid velocities, which every step imposes.
  const bodies::ImposedFaces& imposed_faces() const { return imposed_; }
  // From the flow's current state: the load of the imposed faces (fbm_load.hpp).
  std::vector<bodies::HydrodynamicLoad> loads(const navier_stokes::NavierStokes& flow) const override;
  // sum of alpha times cell volume over the grid: the body's volume as the grid sees it.
  // Collective.
  double grid_volume(std::size_t i) const;
  // The point-sampled (or sub-sampled) indicator.
  std::vector<bodies::IndicatorPatch> cell_fractions(std::size_t i) const override {
    return {bodies_.at(i).patches[kCellPatch]};
  }
  // Grid points tested against body i's shape on this rank at its last move (faces of the
  // three components and cell centres).
  std::size_t points_tested(std::size_t i) const;

 private:
  static constexpr std::size_t kCellPatch = 3;
  struct Entry {
    bodies::RigidBody body;
    std::vector<bodies::IndicatorPatch> patches;  // velocity components 0..2, then cell centres
  };
  void build(Entry& e) const;
  void collect_imposed_faces();

  const grid::Grid& grid_;
  FbmOptions options_;
  std::vector<Entry> bodies_;
  bodies::ImposedFaces imposed_;
};

}  // namespace cosim::fluid::staircase
