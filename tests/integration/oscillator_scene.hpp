// Scenes of the partitioned oscillator (tests/doubles/README.md) for the coupler tests.
#pragma once

#include <string>
#include <vector>

#include "tests/doubles/oscillator_exact.hpp"

namespace cosim::testing {

struct OscillatorScene {
  doubles::Oscillator physics;
  double end = 1.0;
  double window = 0.01;
  double dt_mass = 0.001;
  double dt_spring = 0.001;
  std::string scheme = "serial-implicit";
  std::string acceleration = "iqn-ils";
  double relaxation = 0.5;
  int max_iterations = 100;
  double tolerance = 1e-10;
  double force_tolerance = 0;
  std::string integrator = "verlet";
  std::string transport = "ipc";
  std::string interface;  // coupling.interface if set
  double timeout = 20;
  double heartbeat = 10;
  int checkpoint_every = 10;
  std::vector<std::string> mass_keys, spring_keys;  // more keys of a section, e.g. "hosts: [n1]"
  std::vector<std::string> spring_extra;            // more option lines for the spring, e.g. "kill_at: 0.5"
  std::string spring_command = "[cosim-test-oscillator-spring]";  // its scene key `command`
  std::string output = "run.h5";

  std::string yaml() const;
};

}  // namespace cosim::testing
