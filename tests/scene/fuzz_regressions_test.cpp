// The scenes that crashed the loader under fuzz_scene (tests/fuzz): each now fails with a
// SceneError naming the key. The inputs live in tests/fuzz/regressions/fuzz_scene.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests/scene/errors.hpp"

namespace cosim::scene {
namespace {

std::string regression(const std::string& name) {
  std::ifstream in(std::filesystem::path(COSIM_FUZZ_REGRESSIONS) / "fuzz_scene" / name);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Guards against: a body count of NaN (0 / 0 volumes) converted to an integer, undefined
// behaviour that UBSan reports.
TEST(FuzzRegressions, SolidFractionOfVolumesBelowDoublePrecisionIsRefused) {
  EXPECT_EQ(load_error(regression("random-volumes-underflow.yaml")),
            "scene.yaml:19: bodies[0].solid_fraction = 0.5: gives no number of bodies: the sizes of the region and "
            "the body are below double precision");
}

const std::string too_wide =
    "scene.yaml:3: domain.max = [1.0e308, 1.0e308, 1.0e308]: is too far from domain.min: the box's width is beyond "
    "double precision";

// Guards against: the same from a lattice whose widths overflow (inf - inf).
TEST(FuzzRegressions, LatticeInADomainWiderThanDoublePrecisionIsRefused) {
  EXPECT_EQ(load_error(regression("lattice-widths-overflow.yaml")), too_wide);
}

// Guards against: a cell index of NaN converted to an integer while packing bodies at
// random in a region of infinite width.
TEST(FuzzRegressions, RandomPackingInADomainWiderThanDoublePrecisionIsRefused) {
  EXPECT_EQ(load_error(regression("random-domain-overflow.yaml")), too_wide);
}

}  // namespace
}  // namespace cosim::scene
