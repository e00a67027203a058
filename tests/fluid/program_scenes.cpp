#include "program_scenes.hpp"

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

}  // namespace cosim::testing
