#include <stdexcept>
#include <string>

#include "coupler/coupling/acceleration.hpp"

namespace cosim::coupling {

std::unique_ptr<Accelerator> make_accelerator(Acceleration kind, double w) {
  switch (kind) {
    case Acceleration::None:
      return make_fixed_point();
    case Acceleration::Constant:
      return make_constant(w);
    case Acceleration::Aitken:
      return make_aitken(w);
    case Acceleration::IqnIls:
      return make_iqn_ils(w);
  }
  // Reached only through a cast from an integer that names no enumerator.
  throw std::invalid_argument("unknown acceleration " + std::to_string(static_cast<int>(kind)));
}

}  // namespace cosim::coupling
