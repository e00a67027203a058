#include "tests/fluid/program_scenes.hpp"

#include <fmt/format.h>

namespace cosim::testing {

std::string oscillating_cylinder_scene(const std::string& options, double end, double window) {
  return fmt::format(
      "time: {{end: {}}}\n"
      "coupling: {{window: {}, scheme: serial-explicit}}\n"
      "domain: {{min: [0, 0, 0], max: [0.4, 0.2, 0.01]}}\n"
      "effects: [hydrodynamics]\n"
      "bodies:\n"
      "  - {{name: cyl, shape: {{type: cylinder, radius: 0.03, height: 0.01}}, fixed: true, position: [0.2, 0.1, 0.005]}}\n"
      "participants:\n"
      "  fluid:\n"
      "    dt: 0.01\n"
      "    options:\n"
      "      density: 1000\n"
      "      viscosity: {{model: newtonian, mu: 0.01}}\n"
      "      grid: {{cells: [16, 8, 1]}}\n"
      "      boundaries: {{z_min: {{type: periodic}}, z_max: {{type: periodic}}}}\n"
      "      motion: {{cyl: {{type: sinusoidal, amplitude: [0.05, 0, 0], frequency: 2}}}}\n"
      "{}",
      end, window, options);
}

std::string channel_scene(const std::string& file) {
  return fmt::format(R"(time: {{end: 0.1}}
coupling: {{window: 0.05, scheme: serial-explicit}}
output: {{file: {}, fields_every: 1}}
domain: {{min: [0, 0, 0], max: [0.4, 0.2, 0.01]}}
effects: [hydrodynamics]
bodies:
  - {{name: cyl, shape: {{type: cylinder, radius: 0.03, height: 0.01}}, fixed: true, position: [0.2, 0.1, 0.005]}}
participants:
  fluid:
    dt: 0.01
    options:
      density: 1000
      viscosity: {{model: newtonian, mu: 0.01}}
      grid: {{cells: [16, 8, 1], stretching: [1, 0, 0]}}
      boundaries:
        x_min: {{type: inflow, velocity: [0.1, 0, 0]}}
        x_max: {{type: outflow}}
        y_min: {{type: periodic}}
        y_max: {{type: periodic}}
        z_min: {{type: periodic}}
        z_max: {{type: periodic}}
      initial_velocity: [0.1, 0, 0]
      bodies: {{tolerance: 1.0e-9}}  # the forcing converged: two ranks give one rank's answer
)",
                     file);
}

}  // namespace cosim::testing
