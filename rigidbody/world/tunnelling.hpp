// Which bodies move so far in one substep that contacts can miss them. Speculative contacts
// only see gaps below the contact margin, and a body that enters another by more than half
// its own thickness may be pushed out through the far side; both let a fast body pass
// through a thin one. The check is a pure function; TunnellingWarnings logs its findings.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "rigidbody/dynamics/body.hpp"
#include "geometry/shape.hpp"

namespace cosim::rigidbody::world {

struct TunnellingRisk {
  std::uint32_t body = 0;
  double travel = 0.0;    // largest distance per substep: (|v| + speed_gain) dt [m]
  double thinnest = 0.0;  // the body's thinnest extent [m]
  double margin = 0.0;    // the contact margin [m]
};

// Width of the shape along its thinnest body axis, or across its thinnest face for a convex
// hull; +infinity for a half-space. Exact for every analytic shape.
double thinnest_extent(const geometry::Shape& shape);

// Bodies (not fixed) whose travel in one substep of `dt` exceeds the margin or half their
// thinnest extent (one per body, see thinnest_extent), in body order. `speed_gain` bounds how much faster a body may
// get during the coming window (|g| times the window under gravity): a falling body is caught before it reaches the
// speed, not one window later.
std::vector<TunnellingRisk> tunnelling_risks(std::span<const double> thinnest,
                                             std::span<const dynamics::BodyState> states,
                                             std::span<const dynamics::BodyInertia> inertias, double dt, double margin,
                                             double speed_gain);

// How many times the body's travel exceeds the smaller of its two limits (the margin and
// half its thinnest extent): the factor by which dt must shrink.
double excess(const TunnellingRisk& risk);

// "body 1 (plate) may move 0.0501 m per substep (dt = 0.001 s), more than the contact margin
// 0.0141 m and half its thinnest extent 0.0025 m: it can pass through thin bodies or
// planes; lower the rigidbody dt by a factor 20, to 4.99e-05 s"
std::string describe(const TunnellingRisk& risk, const std::string& name, double dt);

// A body's name, for warnings.
struct NamedBody {
  std::uint32_t body = 0;
  std::string name;
};

// One message for all of a window's risks: describe() of the one with the largest excess,
// whose safe dt is safe for all, preceded by the count when there are several ("12 bodies
// may move farther per substep than ...; the worst: body 17 (grain) may move ..."). `names`:
// the bodies that have one, in body order.
std::string summarise(std::span<const TunnellingRisk> risks, std::span<const NamedBody> names, double dt);

// Decides when summarise() is worth saying: one warning, not one per body, the first time
// any body is at risk, and again only when the count or the worst excess has doubled since
// the last warning (a granular bed gathering speed gives a handful of lines, not one per
// grain; the count of every window is in StepReport::tunnelling_bodies).
class TunnellingWarnings {
 public:
  void add(std::string name, const geometry::Shape& shape);  // one per body, in body order
  void reserve(std::size_t bodies) { thinnest_.reserve(bodies); }
  std::span<const double> thinnest() const { return thinnest_; }
  // summarise() when it is to be said now; nothing otherwise.
  std::optional<std::string> warning(std::span<const TunnellingRisk> risks, double dt);

 private:
  // Only the bodies that have a name: most have none, and an empty string in every body's
  // place would hold 32 bytes per body.
  std::vector<NamedBody> names_;
  std::vector<double> thinnest_;  // thinnest_extent per body, computed once
  std::size_t warned_count_ = 0;  // at the last warning; 0: none yet
  double warned_excess_ = 0.0;
};

}  // namespace cosim::rigidbody::world
