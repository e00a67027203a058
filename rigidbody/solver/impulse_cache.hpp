// Per-contact-point memory carried from one step to the next: accumulated impulses for
// warm starting the impulse solvers, tangential spring stretch for DEM. The contact graph
// owns one and hands it to the solver every step.
#pragma once

#include <cstddef>
#include <cstdint>
#include <unordered_map>

#include <Eigen/Core>

namespace cosim::solver {

struct ContactKey {
  std::uint32_t a = 0;
  std::uint32_t b = 0;
  std::uint32_t feature = 0;
  bool operator==(const ContactKey&) const = default;
};

struct ContactKeyHash {
  std::size_t operator()(const ContactKey& k) const noexcept;
};

// World-frame vectors, so a normal that turns a little between steps only needs the
// stored vector projected onto the new tangent plane, not a matching tangent basis.
struct CachedContact {
  double normal = 0.0;                                   // normal impulse [N s]
  Eigen::Vector3d tangent = Eigen::Vector3d::Zero();     // friction impulse [N s]
  Eigen::Vector3d stretch = Eigen::Vector3d::Zero();     // DEM tangential spring [m]
};

// A solver reads the previous step's entries and replaces the whole content with the
// current contacts, so points that vanished are forgotten.
class ContactImpulses {
 public:
  const CachedContact* find(const ContactKey& key) const;
  void store(const ContactKey& key, const CachedContact& value) { entries_[key] = value; }
  void clear() { entries_.clear(); }
  std::size_t size() const { return entries_.size(); }
  void swap(ContactImpulses& other) noexcept { entries_.swap(other.entries_); }

 private:
  std::unordered_map<ContactKey, CachedContact, ContactKeyHash> entries_;
};

}  // namespace cosim::solver
