#pragma once
// A Maxwellian stream entering the domain through boundary faces (Bird 1994, sections 4.3
// and 12.1): per face and step, the number of simulators crossing inward, each with a
// velocity from the flux-weighted distribution and a uniform point of the face, moved into
// the domain for a random part of the step. Particles leave through the same faces when
// their patches are `open`, so a box with an inflow on every side holds the stream's
// density at equilibrium.

#include "tracker/tracking/swarm.hpp"

#include <functional>
#include <vector>

namespace cosim::tracker::tracking {

struct Stream {
  double number_density = 0.0;   // real molecules per m^3
  Vec3 velocity = Vec3::Zero();  // m/s
  double temperature = 0.0;      // K
  double mass = 0.0;             // kg
  double weight = 1.0;           // real molecules per simulator (fnum)
};

class Inflow {
 public:
  // The boundary faces of `patches` (indices into Mesh::patches); on a part of a mesh
  // (mesh/part.hpp), those of its own cells. Throws std::invalid_argument for a
  // non-positive density, temperature, mass or weight, or a patch without faces (in a
  // whole mesh). Keeps a reference to the mesh.
  Inflow(const mesh::Mesh& mesh, const std::vector<Index>& patches, const Stream& stream);

  // The same stream through the same patches of another mesh (a rank's new part).
  Inflow on(const mesh::Mesh& mesh) const { return Inflow(mesh, patches_, stream_); }
  // Simulators entering per second through all the faces (the mean of inject / dt).
  double rate() const { return rate_; }
  double temperature() const { return stream_.temperature; }
  // Adds the simulators entering during dt to the swarm (states by direct evaluation at
  // the face), each moved by the event-driven tracking for a uniform random part of dt.
  // The count per face is the expected one rounded up or down at random (unbiased).
  // Returns how many entered, those that left again within dt included (they count in
  // step.moves.removed), so particles = seeded + entered - removed. The moves add to the
  // step's tallies as move() does. On a part of a mesh, a particle whose move enters a
  // ghost goes to step.away with the rest of its move (Swarm::move_all).
  long inject(const MoveContext& step, double dt, Swarm& swarm) const;

 private:
  // A face's constants, fixed at construction.
  struct Entry {
    Index face;
    Index cell;
    double rate;         // simulators per second
    double speed_ratio;  // s = (stream . inward normal) / most probable speed
    double area;
    Vec3 t1, t2;  // tangents: the stream's tangential part is (stream.t1, stream.t2)
  };
  Vec3 point_on(const Entry& entry, Random& random) const;
  Vec3 velocity(const Entry& entry, Random& random) const;

  const mesh::Mesh& mesh_;
  std::vector<Index> patches_;
  Stream stream_;
  double most_probable_;  // sqrt(2 k T / m)
  std::vector<Entry> entries_;
  double rate_ = 0.0;
};

// Inward flux of a Maxwellian at rest-frame speed ratio s normal to a face, per unit area
// and number density, in units of the most probable speed: (e^(-s^2) + sqrt(pi) s
// (1 + erf s)) / (2 sqrt(pi)).
double flux_factor(double s);
// A normal velocity (in units of the most probable speed) from the inflow distribution
// x e^(-(x - s)^2), x > 0, by inverting its cumulative distribution.
double inflow_normal_speed(double s, double u);

}  // namespace cosim::tracker::tracking
