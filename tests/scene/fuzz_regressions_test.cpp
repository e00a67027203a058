// The scenes fuzz_scene (tests/fuzz) found to crash the loader: each now fails with a
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
            "scene.yaml:19: bodies[0].solid_fraction = 0.5: gives no number of bodies: the sizes of the region or "
            "the body are beyond double precision");
}

// Guards against: the same from a lattice whose widths overflow (inf - inf).
TEST(FuzzRegressions, LatticeOfWidthsBeyondDoublePrecisionIsRefused) {
  EXPECT_EQ(load_error(regression("lattice-widths-overflow.yaml")),
            "scene.yaml:11: bodies[0].spacing = [1, 1, 1]: gives no number of bodies: the sizes of the region or the "
            "body are beyond double precision");
}

}  // namespace
}  // namespace cosim::scene
