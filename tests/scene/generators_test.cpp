// Entries of `bodies:` that make many bodies: lattices, name patterns, and what the
// generated bodies share. `head` is lines 1-3; `bodies:` is line 4, the entry from line 5.
#include <gtest/gtest.h>

#include <cmath>

#include "tests/scene/errors.hpp"

namespace cosim::scene {
namespace {

// A generator entry one key a line: `generate: <kind>` is line 5, keys[i] is line 6 + i.
std::string entry(const std::string& kind, const std::vector<std::string>& keys) {
  std::string text = "  - generate: " + kind + "\n";
  for (const std::string& k : keys) text += "    " + k + "\n";
  return text;
}

Scene load(const std::string& bodies) { return load_scene_from_string(head + "bodies:\n" + bodies, "scene.yaml"); }
std::string error(const std::string& bodies) { return load_error(head + "bodies:\n" + bodies); }

const std::string ball = "shape: {type: sphere, radius: 0.05}";
const std::string glass = "material: {density: 2500}";
const std::string box = "region: {min: [0, 0, 0], max: [0.5, 0.4, 0.3]}";

// A lattice of spheres r = 0.05 in `box`: lines 6-9 are name, shape, material, region.
std::string lattice(const std::vector<std::string>& keys) {
  std::vector<std::string> all{"name: \"b{:03d}\"", ball, glass, box};
  all.insert(all.end(), keys.begin(), keys.end());
  return entry("lattice", all);
}

void expect_near(const Vec3& a, const Vec3& b) {
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k], b[k], 1e-12) << "axis " << k;
}

TEST(Lattice, CountSpreadsTheBodiesOverTheRegionXFastest) {
  // Centres may go 0.05 in from each face: 0.4 x 0.3 x 0.2 for 3 x 2 x 1 steps.
  const Scene s = load(lattice({"count: [4, 3, 2]"}));
  ASSERT_EQ(s.bodies.size(), 24u);
  EXPECT_EQ(s.bodies[0].name, "b000");
  EXPECT_EQ(s.bodies[23].name, "b023");
  expect_near(s.bodies[0].position, {0.05, 0.05, 0.05});
  expect_near(s.bodies[1].position, {0.05 + 0.4 / 3, 0.05, 0.05});
  expect_near(s.bodies[4].position, {0.05, 0.2, 0.05});
  expect_near(s.bodies[12].position, {0.05, 0.05, 0.25});
  expect_near(s.bodies[23].position, {0.45, 0.35, 0.25});
  for (const Body& b : s.bodies) {
    EXPECT_EQ(b.shape.radius, 0.05);
    EXPECT_EQ(b.material.density, 2500);
  }
  ASSERT_EQ(s.generators.size(), 1u);
  EXPECT_EQ(s.generators[0].entry, 0u);
  EXPECT_EQ(s.generators[0].kind, Generator::Lattice);
  EXPECT_EQ(s.generators[0].first, 0u);
  EXPECT_EQ(s.generators[0].count, 24u);
}

TEST(Lattice, SpacingAloneFitsAsManyAsTheRegionHoldsCentred) {
  // 0.4 / 0.1 + 1 = 5 along x, 4 along y, 3 along z; at 0.12 apart 4 fit along x, and the
  // 0.04 left over is shared by both ends.
  const Scene s = load(lattice({"spacing: [0.1, 0.1, 0.1]"}));
  ASSERT_EQ(s.bodies.size(), 60u);
  expect_near(s.bodies[0].position, {0.05, 0.05, 0.05});
  expect_near(s.bodies[59].position, {0.45, 0.35, 0.25});
  const Scene loose = load(lattice({"spacing: [0.12, 0.1, 0.1]"}));
  ASSERT_EQ(loose.bodies.size(), 48u);  // 4 along x: 0.36 of 0.4
  expect_near(loose.bodies[0].position, {0.07, 0.05, 0.05});
}

TEST(Lattice, CountAndSpacingTogetherAreCentredInTheRegion) {
  const Scene s = load(lattice({"count: [2, 1, 1]", "spacing: [0.2, 1, 1]"}));
  ASSERT_EQ(s.bodies.size(), 2u);
  expect_near(s.bodies[0].position, {0.15, 0.2, 0.15});
  expect_near(s.bodies[1].position, {0.35, 0.2, 0.15});
}

TEST(Lattice, JitterStaysWithinItsBoundAndTheRegionAndFollowsTheSeed) {
  // With jitter 0.01 the centres' span shrinks by 0.02: 0.38 x 0.28 x 0.18.
  const auto jittered = [](const std::string& seed) {
    return load(lattice({"count: [4, 3, 2]", "jitter: 0.01", "seed: " + seed}));
  };
  const Scene s = jittered("7");
  ASSERT_EQ(s.bodies.size(), 24u);
  const Vec3 first{0.06, 0.06, 0.06}, step{0.38 / 3, 0.14, 0.18};
  double largest = 0;
  for (std::size_t n = 0; n < s.bodies.size(); ++n) {
    const std::array<std::size_t, 3> at{n % 4, n / 4 % 3, n / 12};
    for (int k = 0; k < 3; ++k) {
      const double offset = s.bodies[n].position[k] - (first[k] + static_cast<double>(at[k]) * step[k]);
      EXPECT_LE(std::abs(offset), 0.01 + 1e-12) << s.bodies[n].name;
      largest = std::max(largest, std::abs(offset));
      EXPECT_GE(s.bodies[n].position[k] - 0.05, -1e-12);
    }
    EXPECT_LE(s.bodies[n].position[0] + 0.05, 0.5 + 1e-12);
    EXPECT_LE(s.bodies[n].position[1] + 0.05, 0.4 + 1e-12);
    EXPECT_LE(s.bodies[n].position[2] + 0.05, 0.3 + 1e-12);
  }
  EXPECT_GT(largest, 0.008);  // 72 offsets uniform in [-0.01, 0.01]: they do move
  const Scene again = jittered("7"), other = jittered("8");
  for (std::size_t n = 0; n < s.bodies.size(); ++n) EXPECT_EQ(again.bodies[n].position, s.bodies[n].position);
  EXPECT_NE(other.bodies[5].position, s.bodies[5].position);
}

TEST(Lattice, JitterPerAxis) {
  const Scene s = load(lattice({"count: [4, 3, 2]", "jitter: [0.01, 0.01, 0]"}));
  expect_near(s.bodies[0].position, {s.bodies[0].position[0], s.bodies[0].position[1], 0.05});
  expect_near(s.bodies[23].position, {s.bodies[23].position[0], s.bodies[23].position[1], 0.25});
}

TEST(Lattice, BodiesThatDoNotFit) {
  EXPECT_EQ(error(lattice({"count: [6, 1, 1]", "spacing: [0.1, 0.1, 0.1]"})),
            "scene.yaml:10: bodies[0].count = [6, 1, 1]: 6 bodies 0.1 apart on x take 0.6, more than the region's 0.5");
  EXPECT_EQ(error(lattice({"spacing: [0.08, 0.1, 0.1]"})),
            "scene.yaml:10: bodies[0].spacing = [0.08, 0.1, 0.1]: puts bodies 0.08 apart on x, closer than their width "
            "and twice the jitter (0.1): they could overlap");
  EXPECT_EQ(error(lattice({"count: [1, 4, 1]", "jitter: 0.01"})),
            "scene.yaml:10: bodies[0].count = [1, 4, 1]: puts bodies 0.0933333 apart on y, closer than their width and "
            "twice the jitter (0.12): they could overlap");
  EXPECT_EQ(error(entry("lattice", {"name: \"b{}\"", ball, glass, "region: {min: [0, 0, 0], max: [0.5, 0.09, 0.5]}",
                                    "count: [1, 1, 1]"})),
            "scene.yaml:9: bodies[0].region = {min: [0, 0, 0], max: [0.5, 0.09, 0.5]}: is 0.09 wide on y, less than a "
            "body and its jitter take (0.1)");
}

TEST(Lattice, MissingOrMalformedCounts) {
  EXPECT_EQ(error(lattice({})), "scene.yaml:5: bodies[0].count: missing: a lattice needs count, spacing or both");
  EXPECT_EQ(error(lattice({"count: [4, 3.5, 2]"})),
            "scene.yaml:10: bodies[0].count = [4, 3.5, 2]: expected a list of 3 integers");
  EXPECT_EQ(error(lattice({"count: [4, 0, 2]"})),
            "scene.yaml:10: bodies[0].count = [4, 0, 2]: every entry must be >= 1");
  EXPECT_EQ(error(lattice({"spacing: [0.1, 0, 0.1]"})),
            "scene.yaml:10: bodies[0].spacing = [0.1, 0, 0.1]: every entry must be > 0");
  EXPECT_EQ(error(lattice({"count: [1, 1, 1]", "jitter: -0.01"})),
            "scene.yaml:11: bodies[0].jitter = -0.01: must be >= 0");
  EXPECT_EQ(error(lattice({"spacing: [1.0e-5, 1.0e-5, 1.0e-5]"})),
            "scene.yaml:10: bodies[0].spacing = [1.0e-5, 1.0e-5, 1.0e-5]: puts bodies 1e-05 apart on x, closer than "
            "their width and twice the jitter (0.1): they could overlap");
}

TEST(Lattice, TooManyBodiesForOneEntry) {
  EXPECT_EQ(error(entry("lattice", {"name: \"b{}\"", "shape: {type: sphere, radius: 1.0e-5}", glass,
                                    "region: {min: [0, 0, 0], max: [1, 1, 1]}", "spacing: [1.0e-4, 1.0e-4, 1.0e-4]"})),
            "scene.yaml:10: bodies[0].spacing = [1.0e-4, 1.0e-4, 1.0e-4]: makes 1e+12 bodies; one entry makes at most "
            "10000000");
}

TEST(Generators, RegionMustLieInsideTheDomain) {
  EXPECT_EQ(error(entry("lattice", {"name: \"b{}\"", ball, glass, "region:", "  min: [0, 0, 0]", "  max: [1.5, 1, 1]",
                                    "count: [1, 1, 1]"})),
            "scene.yaml:11: bodies[0].region.max = [1.5, 1, 1]: outside the domain [0, 0, 0] .. [1, 1, 1]");
  EXPECT_EQ(
      error(entry("random", {"name: \"b{}\"", ball, glass, "region: {min: [-0.1, 0, 0], max: [1, 1, 1]}", "count: 1"})),
      "scene.yaml:9: bodies[0].region.min = [-0.1, 0, 0]: outside the domain [0, 0, 0] .. [1, 1, 1]");
  EXPECT_EQ(error(entry("lattice", {"name: \"b{}\"", ball, glass, "region: {min: [0, 0, 0], max: [1, 0, 1]}"})),
            "scene.yaml:9: bodies[0].region.max = [1, 0, 1]: must be greater than bodies[0].region.min in every "
            "component");
}

TEST(Generators, NamePatternIsFormattedWithTheIndex) {
  const Scene s = load(entry("lattice", {"name: \"grain-{}\"", ball, glass, box, "count: [4, 3, 1]"}));
  ASSERT_EQ(s.bodies.size(), 12u);
  EXPECT_EQ(s.bodies[0].name, "grain-0");
  EXPECT_EQ(s.bodies[11].name, "grain-11");
  const Scene hex = load(entry("lattice", {"name: \"{:02x}_p\"", ball, glass, box, "count: [4, 3, 1]"}));
  EXPECT_EQ(hex.bodies[11].name, "0b_p");
}

TEST(Generators, BadNamePatterns) {
  const auto named = [](const std::string& pattern) {
    return error(entry("lattice", {"name: " + pattern, ball, glass, box, "count: [4, 3, 1]"}));
  };
  EXPECT_EQ(named("ball"),
            "scene.yaml:6: bodies[0].name = ball: has no field for the index, so every body would get the same name; "
            "write it as {} or {:03d}");
  EXPECT_EQ(named("\"b{:q}\""),
            "scene.yaml:6: bodies[0].name = \"b{:q}\": not a name pattern (invalid type specifier); write the index "
            "as {} or {:03d}");
  EXPECT_EQ(named("\"b{}{}\""),
            "scene.yaml:6: bodies[0].name = \"b{}{}\": not a name pattern (argument not found); write the index as {} "
            "or {:03d}");
  EXPECT_EQ(named("\"b {}\""),
            "scene.yaml:6: bodies[0].name = \"b {}\": makes 'b 0' for index 0: expected a name of 1 to 31 letters, "
            "digits, '_' and '-'");
  EXPECT_EQ(named("\"b{:>40}\""),
            "scene.yaml:6: bodies[0].name = \"b{:>40}\": makes 'b                                       0' for "
            "index 0: expected a name of 1 to 31 letters, digits, '_' and '-'");
}

TEST(Generators, NamesMustBeUniqueAcrossGeneratedAndSingleBodies) {
  const std::string single = "  - {name: b003, " + ball + ", " + glass + ", position: [0.9, 0.9, 0.9]}\n";
  // The single body at line 5, the generator from line 6.
  EXPECT_EQ(error(single + lattice({"count: [4, 3, 2]"})),
            "scene.yaml:7: bodies[1].name = \"b{:03d}\": makes 'b003', a name bodies[0] has already");
  // The generator at lines 5-10, the single body at line 11.
  EXPECT_EQ(error(lattice({"count: [4, 3, 2]"}) + single),
            "scene.yaml:11: bodies[1].name = b003: duplicate body name (first at bodies[0])");
  EXPECT_EQ(error(lattice({"count: [4, 3, 2]"}) +
                  entry("random",
                        {"name: \"b{:03d}\"", ball, glass, "region: {min: [0, 0, 0.5], max: [1, 1, 1]}", "count: 1"})),
            "scene.yaml:12: bodies[1].name = \"b{:03d}\": makes 'b000', a name bodies[0] has already");
}

TEST(Generators, EveryBodySharesTheEntrysKeys) {
  const Scene s =
      load(entry("lattice", {"name: \"p{}\"", "shape: {type: box, half_extents: [0.05, 0.02, 0.01]}", "fixed: true",
                             "orientation: [0.70710678, 0, 0, 0.70710678]", "velocity: [0, 0, -1]",
                             "angular_velocity: [1, 0, 0]", box, "count: [2, 2, 2]"}));
  ASSERT_EQ(s.bodies.size(), 8u);
  for (const Body& b : s.bodies) {
    EXPECT_TRUE(b.fixed);
    EXPECT_EQ(b.material.density, 0.0);
    EXPECT_EQ(b.shape.type, ShapeType::Box);
    EXPECT_NEAR(b.orientation[0], std::sqrt(0.5), 1e-12);
    EXPECT_NEAR(b.orientation[3], std::sqrt(0.5), 1e-12);
    EXPECT_EQ(b.velocity, (Vec3{0, 0, -1}));
    EXPECT_EQ(b.angular_velocity, (Vec3{1, 0, 0}));
  }
  // Turned a quarter about z, the box is 0.04 wide on x and 0.1 on y: the lattice keeps that
  // whole box in the region.
  expect_near(s.bodies[0].position, {0.02, 0.05, 0.01});
  expect_near(s.bodies[7].position, {0.48, 0.35, 0.29});
}

TEST(Generators, MixWithSingleBodiesInFileOrder) {
  const auto lid = [](const std::string& name) {
    return "  - {name: " + name + ", fixed: true, shape: {type: plane, normal: [0, 0, -1]}, position: [0.5, 0.5, 1]}\n";
  };
  const Scene s = load(lid("lid") + lattice({"count: [2, 1, 1]"}) + lid("lid2"));
  ASSERT_EQ(s.bodies.size(), 4u);
  EXPECT_EQ(s.body_names(), (std::vector<std::string>{"lid", "b000", "b001", "lid2"}));
  ASSERT_EQ(s.generators.size(), 1u);
  EXPECT_EQ(s.generators[0].entry, 1u);
  EXPECT_EQ(s.generators[0].first, 1u);
  EXPECT_EQ(s.generators[0].count, 2u);
}

TEST(Generators, UnboundedShapesAndUnknownKeys) {
  EXPECT_EQ(error(entry("lattice", {"name: \"w{}\"", "fixed: true", "shape: {type: plane, normal: [0, 0, 1]}", box,
                                    "count: [1, 1, 1]"})),
            "scene.yaml:8: bodies[0].shape = {type: plane, normal: [0, 0, 1]}: generated bodies need a shape of known "
            "extent: give each plane or mesh an entry of its own");
  EXPECT_EQ(error(lattice({"count: [1, 1, 1]", "seeed: 3"})),
            "scene.yaml:11: bodies[0].seeed = 3: unknown key; expected one of: generate, name, fixed, shape, material, "
            "orientation, velocity, angular_velocity, region, count, spacing, jitter, seed");
  EXPECT_EQ(error(lattice({"count: [1, 1, 1]", "position: [0, 0, 0]"})).substr(0, 60),
            "scene.yaml:11: bodies[0].position = [0, 0, 0]: unknown key; ");
  EXPECT_EQ(error(entry("pile", {})),
            "scene.yaml:5: bodies[0].generate = pile: expected one of: lattice, random, file");
}

}  // namespace
}  // namespace cosim::scene
