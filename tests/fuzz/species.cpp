// fuzz_species: the DSMC species file reader on any file. It either returns a table or
// throws SpeciesError; anything else is a finding.
#include "tests/fuzz/scratch_file.hpp"
#include "tracker/dsmc/species.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = cosim::fuzz::scratch_file(data, size, ".yaml");
  try {
    cosim::tracker::dsmc::read_species(file);
  } catch (const cosim::tracker::dsmc::SpeciesError&) {
  }
  return 0;
}
