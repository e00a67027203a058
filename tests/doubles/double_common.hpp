// What the oscillator doubles share: common options, failure injection for the
// coupler's robustness tests (die, hang, be slow), the integrator step and main().
#pragma once

#include <limits>

#include "coupler/participant/solver.hpp"
#include "coupler/protocol/message.hpp"
#include "coupler/scene/reader.hpp"

namespace cosim::doubles {

enum class Integrator { Verlet, Euler };

struct Common {
  Integrator integrator = Integrator::Verlet;
  double dt = 0.0;
  double delay = 0.0;
  double kill_at = std::numeric_limits<double>::infinity();
  double hang_at = std::numeric_limits<double>::infinity();
  std::string kill_marker;  // if set: die only while this file does not exist, then create it

  // Reads the keys every double shares from its options.
  static Common read(const scene::Scene& scene, const scene::Participant& p, const scene::Reader& options);
  // Called at the start of every window.
  void on_window(const participant::Window& w) const;
};

const scene::Participant& section(const scene::Scene& scene, const std::string& name);

// main() of a double: connect to the coupler that started it and serve until Stop.
int serve(const char* program, participant::Solver& solver, scene::Data provides, scene::Data needs);

// One step of the chosen integrator for x'' = a(x, s), from s to s + h.
template <class Accel>
void step(Integrator integrator, double& x, double& v, double s, double h, Accel a) {
  if (integrator == Integrator::Euler) {
    v += h * a(x, s);
    x += h * v;
  } else {
    v += 0.5 * h * a(x, s);
    x += h * v;
    v += 0.5 * h * a(x, s + h);
  }
}

}  // namespace cosim::doubles
