// Small scenes for the cosim-fluid program tests.
#pragma once

#include <string>

namespace cosim::testing {

// A closed 0.4 x 0.2 x 0.01 box, one periodic layer in z (2D), 16 x 8 cells, with a
// cylinder (r = 0.03) oscillating along x: `options` is appended to the fluid's options
// (indented by 6), `end` and `window` set the run.
std::string oscillating_cylinder_scene(const std::string& options = "", double end = 0.2, double window = 0.05);

// Uniform inflow at 0.1 m/s past a fixed cylinder, periodic across: 16 x 8 x 1 cells, 0.025 m
// across and along x stretched towards both ends (symmetric, so cell 8 starts at x = 0.2),
// fields at three times (0, 0.05, 0.1) into `file`.
std::string channel_scene(const std::string& file = "run.h5");

}  // namespace cosim::testing
