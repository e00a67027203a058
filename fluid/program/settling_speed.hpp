// The speed a body settles at, alone in unbounded fluid at rest: the speed the estimate of a
// run expects the fluid around a free body to reach (fluid_work.hpp).
#pragma once

#include "fluid/viscous/viscosity_model.hpp"

namespace cosim::fluid::program {

// The terminal speed of a sphere of the body's volume, `diameter` = (6 V / pi)^(1/3), of
// density `body_density` in a fluid of `fluid_density` and `viscosity` under gravity
// `gravity` (its magnitude), by Schiller & Naumann's drag, C_D = 24 / Re (1 + 0.15
// Re^0.687), and C_D = 0.44 above Re 1000 (Clift, Grace & Weber 1978, Table 5.2). A
// generalized-Newtonian viscosity is taken at the shear rate speed / diameter. Walls and
// other bodies slow a body down, so this is an upper bound for the estimate. 0 for a body
// as dense as the fluid or without gravity.
double settling_speed(double diameter, double body_density, double fluid_density,
                      const fluid::viscous::ViscosityModel& viscosity, double gravity);

}  // namespace cosim::fluid::program
