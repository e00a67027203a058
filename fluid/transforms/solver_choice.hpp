#pragma once
// The choice between a transform solver and a Krylov one, shared by the pressure
// (`-pressure_solver`) and the viscous half-step (`-viscous_solver`).
#include <string>

namespace cosim::fluid::transforms {

// -<prefix>_solver fft|krylov, or, unset, fft where it applies unless a -<prefix>_ksp_* or
// -<prefix>_pc_* flag asks for the Krylov solver. obstacle: why the transforms do not apply
// here, empty where they do. Throws std::invalid_argument naming the option and value for
// another value, or for fft where it does not apply.
bool use_transforms(const std::string& prefix, const std::string& obstacle);

}  // namespace cosim::fluid::transforms
