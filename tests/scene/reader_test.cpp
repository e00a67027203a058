// Reader is also the API every program validates its own options with.
#include "coupler/scene/reader.hpp"

#include <gtest/gtest.h>

#include <array>

#include "tests/scene/errors.hpp"

namespace cosim::scene {
namespace {

Reader options(const std::string& yaml) { return Reader(YAML::Load(yaml), "scene.yaml", "participants.fluid.options"); }

constexpr std::array colours{"red", "green", "blue"};

TEST(Reader, ReadsEveryKindOfValue) {
  const Reader r = options(R"(cfl: 0.5
steps: 1e3
name: "pisoFoam"
verbose: yes
origin: [1, 2.5, -3]
args: [-n, 4]
colour: green
colours: [blue, red]
grid: {cells: 64}
blocks: [{cells: 8}, {cells: 16}]
raw: {anything: [1, 2]}
)");
  EXPECT_EQ(r.number("cfl"), 0.5);
  EXPECT_EQ(r.integer("steps"), 1000);
  EXPECT_EQ(r.string("name"), "pisoFoam");
  EXPECT_TRUE(r.boolean("verbose"));
  EXPECT_EQ(r.vec3("origin"), (Vec3{1, 2.5, -3}));
  EXPECT_EQ(r.strings("args"), (std::vector<std::string>{"-n", "4"}));
  EXPECT_EQ(r.choice("colour", colours), 1u);
  EXPECT_EQ(r.choices("colours", colours), (std::vector<std::size_t>{2, 0}));
  const Reader grid = r.map("grid");
  EXPECT_EQ(grid.integer("cells"), 64);
  EXPECT_EQ(grid.path("cells"), "participants.fluid.options.grid.cells");
  const std::vector<Reader> blocks = r.maps("blocks");
  ASSERT_EQ(blocks.size(), 2u);
  EXPECT_EQ(blocks[1].integer("cells"), 16);
  EXPECT_EQ(blocks[1].path("cells"), "participants.fluid.options.blocks[1].cells");
  EXPECT_EQ(r.node("raw")["anything"][1].as<int>(), 2);
  EXPECT_EQ(r.line("grid"), 9);
  EXPECT_NO_THROW(r.finish());
}

TEST(Reader, FallbacksApplyOnlyToAbsentKeys) {
  const Reader r = options("cfl: 0.9\n");
  EXPECT_EQ(r.number("cfl", 0.5), 0.9);
  EXPECT_EQ(r.number("theta", 0.5), 0.5);
  EXPECT_EQ(r.integer("steps", 7), 7);
  EXPECT_EQ(r.string("name", "x"), "x");
  EXPECT_FALSE(r.boolean("verbose", false));
  EXPECT_EQ(r.vec3("origin", Vec3{1, 2, 3}), (Vec3{1, 2, 3}));
  EXPECT_EQ(r.choice("colour", colours, 2), 2u);
  EXPECT_FALSE(r.has("origin"));
}

TEST(Reader, FinishCatchesAnUnreadKey) {
  const Reader r = options("cfl: 0.5\ncfll: 0.4\n");
  r.number("cfl");
  r.integer("steps", 10);
  EXPECT_EQ(thrown([&] { r.finish(); }),
            "scene.yaml:2: participants.fluid.options.cfll = 0.4: unknown key; expected one of: cfl, steps");
}

TEST(Reader, RangesNameTheBound) {
  const Reader r = options("a: 0\nb: 1.5\nc: 0\nd: [1, -1, 1]\ne: 0\n");
  EXPECT_EQ(thrown([&] { r.number("a", Range::above(0)); }),
            "scene.yaml:1: participants.fluid.options.a = 0: must be > 0");
  EXPECT_EQ(thrown([&] { r.number("b", Range::closed(0, 1)); }),
            "scene.yaml:2: participants.fluid.options.b = 1.5: must be in [0, 1]");
  EXPECT_EQ(thrown([&] { r.integer("c", Range::at_least(1)); }),
            "scene.yaml:3: participants.fluid.options.c = 0: must be >= 1");
  EXPECT_EQ(thrown([&] { r.vec3("d", Range::at_least(0)); }),
            "scene.yaml:4: participants.fluid.options.d = [1, -1, 1]: every entry must be >= 0");
  EXPECT_EQ(thrown([&] { r.number("e", Range::left_open(0, 1)); }),
            "scene.yaml:5: participants.fluid.options.e = 0: must be in (0, 1]");
}

TEST(Reader, WrongTypesSayWhatWasExpected) {
  const Reader r = options(R"(n: fast
q: "1.5"
i: 2.5
b: maybe
v: [1, 2]
s: {a: 1}
m: 3
c: purple
l: [red, red]
x: .inf
)");
  const std::string at = "participants.fluid.options.";
  EXPECT_EQ(thrown([&] { r.number("n"); }), "scene.yaml:1: " + at + "n = fast: expected a number");
  EXPECT_EQ(thrown([&] { r.number("q"); }), "scene.yaml:2: " + at + "q = \"1.5\": expected a number");
  EXPECT_EQ(thrown([&] { r.integer("i"); }), "scene.yaml:3: " + at + "i = 2.5: expected an integer");
  EXPECT_EQ(thrown([&] { r.boolean("b"); }), "scene.yaml:4: " + at + "b = maybe: expected true or false");
  EXPECT_EQ(thrown([&] { r.vec3("v"); }), "scene.yaml:5: " + at + "v = [1, 2]: expected a list of 3 numbers");
  EXPECT_EQ(thrown([&] { r.string("s"); }), "scene.yaml:6: " + at + "s = {a: 1}: expected a string");
  EXPECT_EQ(thrown([&] { r.map("m"); }), "scene.yaml:7: " + at + "m = 3: expected a mapping");
  EXPECT_EQ(thrown([&] { r.choice("c", colours); }),
            "scene.yaml:8: " + at + "c = purple: expected one of: red, green, blue");
  EXPECT_EQ(thrown([&] { r.choices("l", colours); }), "scene.yaml:9: " + at + "l[1] = red: listed twice");
  EXPECT_EQ(thrown([&] { r.number("x"); }), "scene.yaml:10: " + at + "x = .inf: must be finite");
  EXPECT_EQ(thrown([&] { r.number("absent"); }), "scene.yaml:1: " + at + "absent: missing required key");
}

TEST(Reader, RefusesNonMappingsAndRepeatedKeys) {
  EXPECT_EQ(thrown([] { options("[1, 2]"); }), "scene.yaml:1: participants.fluid.options = [1, 2]: expected a mapping");
  EXPECT_EQ(thrown([] { options("cfl: 0.5\nsteps: 3\ncfl: 0.4\n"); }),
            "scene.yaml:3: participants.fluid.options.cfl = 0.4: duplicate key (first at line 1)");
}

TEST(Reader, FailNamesTheKeyAndItsValue) {
  const Reader r = options("a: 1\nsolver: {type: cg, tol: 1}\n");
  EXPECT_EQ(thrown([&] { r.fail("solver", "does not converge"); }),
            "scene.yaml:2: participants.fluid.options.solver = {type: cg, tol: 1}: does not converge");
}

TEST(Reader, ShortensLongValues) {
  const Reader r = options("list: [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15]\n");
  EXPECT_EQ(thrown([&] { r.fail("list", "too long"); }),
            "scene.yaml:1: participants.fluid.options.list = [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 1...: too long");
}

}  // namespace
}  // namespace cosim::scene
