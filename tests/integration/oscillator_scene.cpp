#include "tests/integration/oscillator_scene.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

namespace cosim::testing {

std::string OscillatorScene::yaml() const {
  const double radius = 0.1;
  const double density = physics.m1 / (4.0 / 3.0 * std::numbers::pi * std::pow(radius, 3));
  std::ostringstream s;
  s.precision(17);
  s << "time: {end: " << end << "}\n"
    << "coupling:\n"
    << "  window: " << window << "\n"
    << "  scheme: " << scheme << "\n"
    << "  acceleration: " << acceleration << "\n"
    << "  relaxation: " << relaxation << "\n"
    << "  max_iterations: " << max_iterations << "\n"
    << "  tolerance: " << tolerance << "\n"
    << "  force_tolerance: " << force_tolerance << "\n"
    << "  transport: " << transport << "\n"
    << (interface.empty() ? "" : "  interface: " + interface + "\n") << "  timeout: " << timeout << "\n"
    << "  heartbeat: " << heartbeat << "\n"
    << "output: {file: " << output << ", every: 1, checkpoint_every: " << checkpoint_every << "}\n"
    << "gravity: [0, 0, 0]\n"
    << "domain: {min: [-5, -1, -1], max: [5, 1, 1]}\n"
    << "bodies:\n"
    << "  - name: m1\n"
    << "    shape: {type: sphere, radius: 0.1}\n"
    << "    material: {density: " << density << "}\n"
    << "    position: [" << physics.x1 << ", 0, 0]\n"
    << "    velocity: [" << physics.v1 << ", 0, 0]\n"
    << "participants:\n"
    << "  mass:\n"
    << "    command: [cosim-test-oscillator-mass]\n"
    << "    provides: [poses]\n"
    << "    needs: [forces]\n"
    << "    dt: " << dt_mass << "\n"
    << "    options: {integrator: " << integrator << "}\n";
  for (const auto& line : mass_keys) s << "    " << line << "\n";
  s << "  spring:\n"
    << "    command: " << spring_command << "\n"
    << "    provides: [forces]\n"
    << "    needs: [poses]\n"
    << "    dt: " << dt_spring << "\n";
  for (const auto& line : spring_keys) s << "    " << line << "\n";
  s << "    options:\n"
    << "      integrator: " << integrator << "\n"
    << "      stiffness: " << physics.k << "\n"
    << "      wall_stiffness: " << physics.k2 << "\n"
    << "      mass: " << physics.m2 << "\n"
    << "      rest_length: " << physics.rest << "\n"
    << "      anchor: " << physics.anchor << "\n"
    << "      position: " << physics.x2 << "\n"
    << "      velocity: " << physics.v2 << "\n";
  for (const auto& line : spring_extra) s << "      " << line << "\n";
  return s.str();
}

}  // namespace cosim::testing
