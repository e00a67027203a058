// Which convergence acceleration implicit coupling uses: the scene names it
// (`coupling.acceleration`), make_accelerator() builds it (acceleration.hpp).
#pragma once

namespace cosim::coupling {

enum class Acceleration { None, Constant, Aitken, IqnIls };

}  // namespace cosim::coupling
