// What a contact point carries from one narrow phase to the next: the accumulated impulses that
// warm-start the impulse solvers, or DEM's tangential spring. The solvers take one
// CachedContact per point of the ContactSet (in: last step's, out: this step's);
// ContactMemory finds last step's value for each new point.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "rigidbody/contact/contact_set.hpp"

namespace cosim::rigidbody::solver {

// World-frame vectors, so a normal that turns a little between steps only needs the
// stored vector projected onto the new tangent plane, not a matching tangent basis.
struct CachedContact {
  double normal = 0.0;  // normal impulse of the (last) substep [N s]
  // Impulse solvers: the friction impulse [N s]. DEM: the tangential spring's stretch [m]
  // (Cundall-Strack); a world runs one solver, so one slot serves both.
  Eigen::Vector3d tangential = Eigen::Vector3d::Zero();
};

// Last step's points, keyed by body pair and feature id. Matching by feature is what lets
// a box resting on a box keep its four corner impulses while the points move a little.
class ContactMemory {
 public:
  // One value per point of `contacts`: the remembered point of the same pair and feature,
  // zero for a new point.
  void recall(const contact::ContactSet& contacts, std::vector<CachedContact>& out) const;
  // Replaces what is remembered by these points and values (memory: one per point). The
  // pairs must be sorted by (a, b), as the contact graph produces them; throws
  // std::invalid_argument otherwise.
  void remember(const contact::ContactSet& contacts, std::span<const CachedContact> memory);
  void clear();
  std::size_t size() const { return entries_.size(); }  // points remembered

  // As doubles, for a participant's saved state (a rollback then warm-starts exactly like
  // the run it repeats): appends [pairs, points, (a, b, count) per pair, (feature, normal,
  // tangential) per point]; every integer is exact in a double.
  void save(std::vector<double>& out) const;
  // Reads what save() wrote, which must be all of `in`. Throws std::invalid_argument for
  // anything else, leaving the memory as it was.
  void load(std::span<const double> in);

 private:
  struct Entry {
    std::uint32_t feature;
    CachedContact value;
  };
  std::vector<contact::PairContacts> pairs_;  // sorted by (a, b); first/count index entries_
  std::vector<Entry> entries_;
};

}  // namespace cosim::rigidbody::solver
