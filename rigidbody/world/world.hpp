// The rigid-body simulator's state: bodies with shapes, materials and inertia, stepped
// over coupling windows with contacts (README.md).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "rigidbody/broadphase/hash_grid.hpp"
#include "rigidbody/dynamics/added_inertia.hpp"
#include "rigidbody/dynamics/body.hpp"
#include "rigidbody/dynamics/body_forces.hpp"
#include "geometry/shape.hpp"
#include "rigidbody/narrowphase/narrowphase.hpp"
#include "rigidbody/world/contact_graph.hpp"
#include "rigidbody/world/materials.hpp"
#include "rigidbody/world/report.hpp"
#include "rigidbody/world/settings.hpp"
#include "rigidbody/world/tunnelling.hpp"

namespace cosim::rigidbody::world {

struct BodyDesc {
  geometry::Shape shape;  // body frame, centre of mass at the origin
  dynamics::BodyState state{};
  double density = 1000.0;  // [kg/m^3]; mass and inertia follow from the shape
  BodyMaterial material{};
  bool fixed = false;   // never moves (half-spaces must be fixed)
  bool rotates = true;  // false: translation only
  std::string name{};   // for warnings only
};

class World {
 public:
  // Throws std::invalid_argument for a non-positive dt or a negative contact margin.
  explicit World(const Settings& settings = {});

  // Returns the body's index. Throws std::invalid_argument for an unbounded shape that is
  // not fixed or a dynamic body without positive density.
  std::uint32_t add(const BodyDesc& body);
  // Room for this many bodies in every per-body array: added one by one, the arrays would
  // otherwise grow by doubling and hold up to twice the bytes they need.
  void reserve(std::size_t bodies);

  // Advances all bodies by `window` in substeps of at most settings().dt (the soft step's:
  // dt / soft.substeps). `external` is
  // empty or one wrench per body (the coupler's forces over this window). `added` is empty
  // or one per body: the liquid's added inertia and damping over this window, with which the
  // bodies move, contacts included (dynamics::with_added).
  StepReport advance(double window, std::span<const dynamics::WindowWrench> external = {},
                     std::span<const dynamics::AddedInertia> added = {});

  std::size_t size() const { return states_.size(); }
  double time() const { return time_; }
  // A coupled run sets the clock to each window's start: the substep length follows from
  // (t + window) - t in floating point, so a repeated window must start from the same t.
  void set_time(double t) { time_ = t; }
  const Settings& settings() const { return settings_; }
  std::span<dynamics::BodyState> states() { return states_; }
  std::span<const dynamics::BodyState> states() const { return states_; }
  std::span<const dynamics::BodyInertia> inertias() const { return inertias_; }
  const geometry::Shape& shape(std::uint32_t i) const { return shapes_[i]; }
  const ContactGraph& graph() const { return graph_; }
  // Besides the body states, the only thing a window carries to the next (the soft step's
  // rows live within one dt's narrow phase): a rollback that restores both repeats the
  // steps bit for bit.
  solver::ContactMemory& contact_memory() { return graph_.memory(); }

 private:
  // The stages of a substep with contacts (step.cpp), between the velocity and the position
  // half of the integration: the graph's edges from the broad phase, the contact set from
  // the narrow phase, the velocities from the solver.
  void broad_phase(StepReport& report);
  void narrow_phase(StepReport& report);
  void solve_contacts(double dt, StepReport& report);
  solver::SolveReport solve(const solver::ContactScene& scene, std::span<solver::CachedContact> memory);
  // The soft step's second half, after the positions moved; `last`: the last substep on
  // this narrow phase's points.
  void relax_contacts(StepReport& report, bool last);
  // Counts the bodies that may tunnel in this window's substeps and adds the warning, when
  // one is due, to the report (tunnelling.hpp).
  void check_tunnelling(double window, double substep, StepReport& report);
  double margin() const;

  Settings settings_;
  solver::SoftStep soft_;
  double time_ = 0.0;
  std::vector<geometry::Shape> shapes_;
  // Of curvature, for the lubrication force (infinite: a plane); none without lubrication.
  std::vector<double> radii_;
  std::vector<dynamics::BodyState> states_;
  std::vector<dynamics::BodyInertia> inertias_;
  // What the bodies move with in the current window: inertias_, or with a liquid's added
  // inertia, moving_ and liquid_.
  std::vector<dynamics::BodyInertia> moving_;
  std::vector<dynamics::InLiquid> liquid_;
  std::span<const dynamics::BodyInertia> stepping_;
  std::vector<BodyMaterial> materials_;
  TunnellingWarnings tunnelling_;
  double smallest_radius_ = 0.0;  // of the bounded bodies, for the default margin

  broadphase::HashGrid grid_;  // made from the bodies at each broad phase, no copy of them kept
  ContactGraph graph_;
  std::vector<solver::Material> pair_materials_;
  std::vector<solver::Mobility> mobility_;
  narrowphase::MeshMaps mesh_maps_;
};

}  // namespace cosim::rigidbody::world
