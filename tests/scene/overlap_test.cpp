// Overlapping bodies: spheres exactly, generated bodies by their bounds, through a cell grid
// so that large scenes are checked in linear time. `head` is lines 1-3, `bodies:` line 4.
#include <gtest/gtest.h>

#include <chrono>

#include "coupler/scene/cell_grid.hpp"
#include "tests/scene/errors.hpp"

namespace cosim::scene {
namespace {

std::string sphere(const std::string& name, const std::string& position, const std::string& extra = "") {
  return "  - {name: " + name + ", shape: {type: sphere, radius: 0.1}, material: {density: 1}, position: " + position +
         extra + "}\n";
}
std::string crate(const std::string& name, const std::string& position) {
  return "  - {name: " + name +
         ", shape: {type: box, half_extents: [0.1, 0.1, 0.1]}, fixed: true, position: " + position + "}\n";
}
std::string error(const std::string& bodies) { return load_error(head + "bodies:\n" + bodies); }

TEST(Overlaps, SpheresMayTouchButNotOverlap) {
  EXPECT_EQ(error(sphere("a", "[0.3, 0.5, 0.5]") + sphere("b", "[0.5, 0.5, 0.5]")), "");
  EXPECT_EQ(error(sphere("a", "[0.3, 0.5, 0.5]") + sphere("b", "[0.45, 0.5, 0.5]")),
            "scene.yaml:6: bodies[1].position = [0.45, 0.5, 0.5]: body 'b' at [0.45, 0.5, 0.5] overlaps body 'a' of "
            "bodies[0] by 0.05 m");
  // Fixed or not, as any two spheres.
  EXPECT_EQ(error(sphere("a", "[0.3, 0.5, 0.5]", ", fixed: true") + crate("c", "[0.8, 0.8, 0.8]") +
                  sphere("b", "[0.4, 0.5, 0.5]")),
            "scene.yaml:7: bodies[2].position = [0.4, 0.5, 0.5]: body 'b' at [0.4, 0.5, 0.5] overlaps body 'a' of "
            "bodies[0] by 0.1 m");
}

TEST(Overlaps, WrittenOutShapesOtherThanSpheresMayOverlap) {
  // Their bounds are loose, and scenes stack them on purpose.
  EXPECT_EQ(error(crate("c", "[0.5, 0.5, 0.5]") + crate("d", "[0.5, 0.5, 0.5]") + sphere("a", "[0.5, 0.5, 0.5]")), "");
}

TEST(Overlaps, GeneratedBodiesMustClearEveryBodyByItsBounds) {
  const std::string lattice = R"(  - generate: lattice
    name: "b{}"
    shape: {type: sphere, radius: 0.05}
    material: {density: 1}
    region: {min: [0, 0, 0], max: [0.4, 0.4, 0.1]}
    count: [4, 4, 1]
)";
  EXPECT_EQ(error(crate("c", "[0.8, 0.8, 0.8]") + lattice), "");
  // The crate's edge passes 0.057 from b10's centre, clear of its radius 0.05, but their
  // bounding spheres and boxes cut into each other: next to a generated body, that counts.
  EXPECT_EQ(error(crate("c", "[0.39, 0.39, 0.1]") + lattice),
            "scene.yaml:6: bodies[1].generate = lattice: body 'b10' at [0.25, 0.25, 0.05] may overlap body 'c' of "
            "bodies[0]: their bounding spheres and boxes cut into each other");
  // Listed after the lattice, the sphere is the one that overlaps, b10 first of four.
  EXPECT_EQ(error(lattice + sphere("ball", "[0.3, 0.3, 0.15]")),
            "scene.yaml:11: bodies[1].position = [0.3, 0.3, 0.15]: body 'ball' at [0.3, 0.3, 0.15] overlaps body "
            "'b10' of bodies[0] by 0.0275255 m");
}

TEST(Overlaps, ALatticeOfTouchingBoxesIsFine) {
  // Their bounding spheres overlap, their boxes only touch.
  EXPECT_EQ(error(R"(  - generate: lattice
    name: "b{}"
    shape: {type: box, half_extents: [0.05, 0.05, 0.05]}
    material: {density: 1}
    region: {min: [0, 0, 0], max: [1, 1, 1]}
    spacing: [0.1, 0.1, 0.1]
)"),
            "");
}

// Guards against: the check over all pairs, which takes minutes for 10^5 bodies.
TEST(Overlaps, CheckingALargeSceneTakesLinearTime) {
  const auto start = std::chrono::steady_clock::now();
  const Scene s = load_scene_from_string(head + R"(bodies:
  - generate: lattice
    name: "b{}"
    shape: {type: sphere, radius: 0.01}
    material: {density: 1}
    region: {min: [0, 0, 0], max: [1, 1, 0.8]}
    count: [50, 50, 40]
)");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("a lattice of 100000 touching spheres, with the scene's checks: %.2f s\n", seconds);
  EXPECT_EQ(s.bodies.size(), 100000u);
  EXPECT_LT(seconds, 10.0);  // well under a second in a Release build; 5e9 pairs would take minutes
}

TEST(CellGrid, FindsTheFirstOverlapAmongThoseThatCount) {
  CellGrid grid(0.1);
  grid.add({{0, 0, 0}, 0.05, {0.05, 0.05, 0.05}});
  grid.add({{0.5, 0.5, 0.5}, 10, {10, 10, 10}});  // large: kept aside
  grid.add({{0.08, 0, 0}, 0.05, {0.05, 0.05, 0.05}});
  const Solid probe{{0.06, 0, 0}, 0.05, {0.05, 0.05, 0.05}};
  EXPECT_EQ(grid.first_overlap(probe), 0u);
  EXPECT_EQ(grid.first_overlap(probe, [](std::size_t i) { return i != 0; }), 1u);
  EXPECT_EQ(grid.first_overlap(probe, [](std::size_t i) { return i == 2; }), 2u);
  EXPECT_EQ(grid.first_overlap({{30, 30, 30}, 0.05, {0.05, 0.05, 0.05}}), std::nullopt);
  const Solid huge{{0, 0, 0}, 60, {60, 60, 60}};  // a query over many cells looks at everything
  EXPECT_EQ(grid.first_overlap(huge), 0u);
}

}  // namespace
}  // namespace cosim::scene
