// One coupling window [t0, t1] under the scene's scheme.
//
// Explicit schemes call each participant once: serial-explicit advances the pose provider
// (rigid bodies) with the forces of t0 held constant, then the force providers with poses
// going from those of t0 to the new ones; parallel-explicit advances everyone with the
// values of t0 held constant. Implicit schemes repeat the window until the exchanged data
// stop changing (their change relative to the larger of their values at the window's start
// and end below the tolerance, or the forces' change below force_tolerance) or
// max_iterations is reached:
// serial-implicit iterates on the forces (on the Robin wrenches when the forces come with
// response tensors: participant/robin.hpp), parallel-implicit on poses and forces stacked
// (each block divided by its norm in the first iteration so neither dominates the
// accelerator). Participants that provide neither (observers) go last with the final
// values, in every iteration so their rollback stays in step. A participant that needs
// fields gets the same frame, taken at t0, in every iteration.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "coupler/coupling/acceleration.hpp"
#include "coupler/run/exchange.hpp"
#include "coupler/run/peers.hpp"

namespace cosim::run {

struct WindowResult {
  Exchange end;
  int iterations = 0;
  double residual = 0.0;
  bool converged = true;
  std::map<std::string, double> wall_seconds;  // per participant, summed over iterations
  std::map<std::string, double> substeps;
  std::map<std::string, double> field_bytes;  // forwarded to each participant, over all iterations
};

// Per participant that needs fields, the field arrays its Advance messages carry.
using FieldArrays = std::map<std::string, std::vector<protocol::Array>>;

class WindowRunner {
 public:
  WindowRunner(Peers& peers, Roles roles, const scene::Coupling& coupling);
  WindowResult advance(std::uint64_t window, double t0, double t1, const Exchange& start,
                       const FieldArrays& fields = {});

 private:
  struct Span {
    std::uint64_t window;
    double t0, t1;
    std::string when;  // labels failures
    const FieldArrays& fields;
  };
  // Advance `names` over the span with inputs interpolated from start to end; returns
  // `end` with the outputs of those participants in place, and adds their stats to r.
  Exchange call(const std::vector<std::string>& names, const Span& s, int iteration, const Exchange& start,
                const Exchange& end, WindowResult& r);
  WindowResult serial_explicit(const Span& s, const Exchange& start);
  WindowResult parallel_explicit(const Span& s, const Exchange& start);
  WindowResult serial_implicit(const Span& s, const Exchange& start);
  WindowResult parallel_implicit(const Span& s, const Exchange& start);
  void observe(const Span& s, int iteration, const Exchange& start, WindowResult& r);
  // The forces' relative change within the tolerance, or their change within force_tolerance.
  bool converged(double relative_change, const Eigen::VectorXd& force_change) const;

  Peers& peers_;
  Roles roles_;
  scene::Coupling coupling_;
  std::unique_ptr<coupling::Accelerator> accelerator_;
};

}  // namespace cosim::run
