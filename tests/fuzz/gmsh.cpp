// fuzz_gmsh: the Gmsh mesh reader on any .msh file. It either returns a valid mesh or
// throws std::invalid_argument naming the file; anything else is a finding.
#include <stdexcept>

#include "tests/fuzz/scratch_file.hpp"
#include "tracker/mesh/gmsh_mesh.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = cosim::fuzz::scratch_file(data, size, ".msh");
  try {
    cosim::tracker::mesh::load_gmsh(file);
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
