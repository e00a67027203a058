#pragma once
// CSG objects inside the tracking mesh: walls that reflect or absorb particles at their
// surface, and permeable zones that only count who enters and leaves. Each object is
// registered with the cells of a bounding mesh (by default the tracking mesh itself, see
// tracker/bounding), and every particle carries one logical state per object, over the
// local primitive indices of its bounding cell.

#include "tracker/bounding/cell_object.hpp"
#include "tracker/tracking/boundaries.hpp"

#include <span>
#include <string>
#include <vector>

namespace cosim::tracker::tracking {

struct Domain;
class Swarm;

struct Obstacle {
  std::string name;
  csg::Tree shape;         // in world coordinates at the current pose (see set_pose)
  bool permeable = false;  // a zone: crossed and counted, never reflects
  BoundaryCondition wall;  // impermeable: specular, diffuse, maxwell, or open (absorbs)
};

// What the particles did at one object's surface, summed over moves: the SurfaceTally of its
// hits (hits, absorbed at an open wall, impulse, energy) and what only objects have.
struct ObstacleTally : SurfaceTally {
  long long entered = 0;   // into a permeable zone
  long long left = 0;      // out of a permeable zone
  long long released = 0;  // found inside a wall by their state and let out at its surface:
                           // a repaired state, 0 unless something went wrong
  long long overrun = 0;   // put back in front of a moving wall (Obstacles::set_pose)
  // The moment of the impulse about the object's pose origin (times the mass and the
  // simulator weight over the sampled time: the torque).
  Vec3 angular_impulse = Vec3::Zero();
  void add(const ObstacleTally& other);
  // A hit at x (an absorbed particle: after = 0).
  void exchange(const Vec3& x, const Vec3& origin, const Vec3& before, const Vec3& after);
};

class Obstacles {
 public:
  Obstacles() = default;  // none
  // `bounding` is the mesh the objects are registered with and `bounding_cell[c]` the
  // bounding cell that holds tracking cell c; both default to the tracking mesh itself. A
  // coarser bounding mesh (a box grid aligned with the tracking cells) is for studies of the
  // pruning (bench/tracker_study). Throws std::invalid_argument as CellObject does, or when
  // a wall's condition is invalid (periodic, or re-emitting without a temperature).
  Obstacles(const mesh::Mesh& tracking, std::vector<Obstacle> objects);
  Obstacles(const mesh::Mesh& tracking, std::vector<Obstacle> objects, const mesh::Mesh& bounding,
            std::vector<Index> bounding_cell);
  // The bounding mesh is kept by reference: a temporary would dangle.
  Obstacles(mesh::Mesh&&, std::vector<Obstacle>) = delete;
  Obstacles(const mesh::Mesh&, std::vector<Obstacle>, mesh::Mesh&&, std::vector<Index>) = delete;

  // The same objects at the same poses and motions, registered with another tracking mesh
  // (a rank's part, mesh/part.hpp) as their bounding mesh.
  Obstacles on(const mesh::Mesh& tracking) const;

  int count() const { return static_cast<int>(objects_.size()); }
  bool empty() const { return objects_.empty(); }
  // Some wall re-emits particles (diffuse or maxwell): the tracking needs their mass.
  bool emits() const { return emits_; }
  const Obstacle& object(int i) const { return objects_[static_cast<std::size_t>(i)]; }
  const bounding::CellObject& cells(int i) const { return cells_[static_cast<std::size_t>(i)]; }
  Index bounding_cell(Index cell) const { return bounding_cell_.empty() ? cell : bounding_cell_[cell]; }
  // The objects with primitives in bounding cell b, ascending: the only ones whose states
  // change there. Elsewhere an object is constant and its state is not looked at.
  std::span<const int> active(Index b) const {
    return {active_.data() + active_first_[b], static_cast<std::size_t>(active_first_[b + 1] - active_first_[b])};
  }

  // A particle's states at x in tracking cell `cell` by direct evaluation (away from
  // surfaces only: for seeding), one per object.
  void classify(Index cell, const Vec3& x, std::span<csg::State> states) const;
  // Inside some wall object by these states: such a particle must not be seeded.
  bool inside_wall(Index cell, std::span<const csg::State> states) const;
  // The states after the particle moved from tracking cell `from` to `to` (x as `to` sees
  // it): bits of primitives both bounding cells share are carried over, the others are
  // evaluated directly, which the ring of the registration keeps far from surfaces. Across
  // a periodic face (`shifted`) every bit is evaluated: the primitives on the two sides are
  // different images.
  void transfer(Index from, Index to, const Vec3& x, bool shifted, std::span<csg::State> states) const;

  // Moves object i rigidly to `pose` (world from the frame its shape was given in) over the
  // time dt > 0, between tracking steps: it is registered anew, and every particle's state
  // for it follows the motion relative to the object by the events of csg::sweep, so states
  // stay exact close to the surface. The object should move less than a cell per call. A
  // wall that overruns a particle puts it back just outside where the surface met it (10
  // tolerances off the surface, where direct evaluation is safe) and reflects it off the
  // moving wall by the wall's condition (`tally`: overrun, hits, impulse; absorbed and
  // removed if the wall is open or the point is in no cell). A particle found inside the
  // moved wall with no known entry (the surface came from beyond the cell's ring, a move of
  // more than a cell) is removed and counted as absorbed. Returns how many were overrun.
  long set_pose(int i, const Eigen::Isometry3d& pose, double dt, const Domain& domain, Swarm& swarm, Random& random,
                ObstacleTally& tally);
  const Eigen::Isometry3d& pose(int i) const { return poses_[static_cast<std::size_t>(i)]; }
  // The velocity of object i's material point at x during the step after its last
  // set_pose: that point's displacement over that call's dt (0 after place()). Walls
  // reflect particles in this moving frame.
  Vec3 velocity_at(int i, const Vec3& x) const {
    const Motion& m = motions_[static_cast<std::size_t>(i)];
    return m.dt > 0 ? Vec3((x - m.back * x) / m.dt) : Vec3::Zero();
  }
  // Puts object i at `pose` with no particles to follow it: where it starts, before seeding
  // (its shape given in a body's frame, the body's initial pose).
  void place(int i, const Eigen::Isometry3d& pose);

 private:
  void find_active();
  // Registers object o at `pose`; returns the registration it had.
  bounding::CellObject reregister(int o, const Eigen::Isometry3d& pose);

  const mesh::Mesh* bounding_ = nullptr;
  std::vector<Obstacle> objects_;
  std::vector<Eigen::Isometry3d> poses_;
  // The last set_pose of each object: new-pose point back to where it was, and over what time.
  struct Motion {
    Eigen::Isometry3d back = Eigen::Isometry3d::Identity();
    double dt = 0.0;
  };
  std::vector<Motion> motions_;
  std::vector<bounding::CellObject> cells_;
  std::vector<Index> bounding_cell_;
  bool emits_ = false;               // asked on every move
  std::vector<Index> active_first_;  // bounding cell b: active_[active_first_[b] .. active_first_[b + 1])
  std::vector<int> active_;
};

}  // namespace cosim::tracker::tracking
