// What --vary and --refine make of a scene, and the refinement ratios they imply.
#include <gtest/gtest.h>

#include <algorithm>

#include "coupler/scene/scene.hpp"
#include "coupler/study/argument_error.hpp"
#include "coupler/study/key_path.hpp"
#include "coupler/study/levels.hpp"
#include "coupler/study/refinement.hpp"

namespace cosim::study {
namespace {

const char* kScene = R"(time: {end: 1}
coupling: {window: 0.01}
domain: {min: [0, 0, 0], max: [1, 1, 1]}
effects: [hydrodynamics]
bodies:
  - {name: ball, shape: {type: sphere, radius: 0.1}, material: {density: 2}, position: [0.5, 0.5, 0.5]}
participants:
  rigidbody: {dt: 0.001}
  fluid:
    dt: 0.01
    options: {grid: {cells: [10, 10, 20]}}
)";

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const ArgumentError& e) {
    return e.what();
  }
  return "";
}

TEST(Vary, ValuesAreYamlSoListsKeepTheirCommas) {
  const Varied v = parse_vary("participants.fluid.options.grid.cells=[10,10,20],[20, 20, 40]");
  EXPECT_EQ(v.key, "participants.fluid.options.grid.cells");
  ASSERT_EQ(v.values.size(), 2u);
  EXPECT_EQ(text(v.values[0]), "[10, 10, 20]");
  EXPECT_EQ(text(v.values[1]), "[20, 20, 40]");
  EXPECT_EQ(text(parse_vary("coupling.window=0.01,0.005").values[1]), "0.005");
}

TEST(Vary, BadArgumentsAreNamed) {
  EXPECT_EQ(error_of([] { parse_vary("coupling.window"); }),
            "--vary coupling.window: expected KEY=V1,V2,... (coupling.window=0.01,0.005,0.0025)");
  EXPECT_EQ(error_of([] { parse_vary("coupling.window=0.01"); }),
            "--vary coupling.window=0.01: give at least two values, coarsest first");
  EXPECT_EQ(error_of([] { parse_vary("coupling.window=0.01,,0.005"); }),
            "--vary coupling.window=0.01,,0.005: a value is empty");
  EXPECT_NE(error_of([] { parse_vary("coupling.window=[0.01,0.005"); }), "");
  EXPECT_EQ(error_of([] {
              level_count({parse_vary("a=1,2,3"), parse_vary("b=1,2")});
            }),
            "--vary b=1,2 gives 2 values but --vary a=1,2,3 gives 3: every --vary needs one value per level");
}

TEST(KeyPath, SetsMapKeysAndListEntriesInPlace) {
  YAML::Node doc = YAML::Load(kScene);
  set_at(doc, "bodies.0.position", YAML::Load("[0.4, 0.5, 0.5]"), "--vary");
  set_at(doc, "coupling.relaxation", YAML::Load("0.3"), "--vary");  // a new last key: the loader judges it
  EXPECT_EQ(doc["bodies"][0]["position"][0].as<double>(), 0.4);
  EXPECT_EQ(doc["coupling"]["relaxation"].as<double>(), 0.3);
  EXPECT_EQ(doc["coupling"]["window"].as<double>(), 0.01);
}

TEST(KeyPath, PathsThatAreNotInTheSceneAreNamed) {
  YAML::Node doc = YAML::Load(kScene);
  const YAML::Node v = YAML::Load("1");
  EXPECT_EQ(error_of([&] { set_at(doc, "coupler.window", v, "--vary coupler.window=1,2"); }),
            "--vary coupler.window=1,2: the scene has no key 'coupler' (it has: time, coupling, domain, effects, "
            "bodies, participants)");
  EXPECT_EQ(error_of([&] { set_at(doc, "bodies.1.position", v, "--vary X"); }),
            "--vary X: bodies is a list of 1 entries: expected an index from 0 to 0, not '1'");
  EXPECT_EQ(error_of([&] { set_at(doc, "bodies.ball.position", v, "--vary X"); }),
            "--vary X: bodies is a list of 1 entries: expected an index from 0 to 0, not 'ball'");
  EXPECT_EQ(error_of([&] { set_at(doc, "coupling.window.x", v, "--vary X"); }),
            "--vary X: coupling.window is a value, not a mapping or list: no 'x' in it");
  EXPECT_EQ(error_of([&] { set_at(doc, "coupling..window", v, "--vary X"); }),
            "--vary X: 'coupling..window' is not a key path (keys joined by dots: coupling.window)");
}

TEST(Refine, DividesStepsAndMultipliesCellsFromTheScenesValues) {
  const scene::Scene s = scene::load_scene_from_string(kScene);
  const std::vector<Varied> keys = refine(s, 2, 3);
  ASSERT_EQ(keys.size(), 4u);
  EXPECT_EQ(keys[0].key, "coupling.window");
  EXPECT_EQ(keys[1].key, "participants.rigidbody.dt");
  EXPECT_EQ(keys[2].key, "participants.fluid.dt");
  EXPECT_EQ(keys[3].key, "participants.fluid.options.grid.cells");
  EXPECT_EQ(text(keys[0].values[2]), "0.0025");
  EXPECT_EQ(text(keys[1].values[1]), "0.0005");
  EXPECT_EQ(text(keys[3].values[2]), "[40, 40, 80]");
  EXPECT_EQ(keys[0].argument, "--refine 2");
  // Every variant is a valid scene, its numbers read back as numbers.
  const YAML::Node doc = YAML::Load(s.text);
  for (std::size_t level = 0; level < 3; ++level) {
    YAML::Emitter out;
    out << variant(doc, keys, level);
    const scene::Scene v = scene::load_scene_from_string(out.c_str());
    EXPECT_DOUBLE_EQ(v.coupling.window, 0.01 / (1 << level));
    EXPECT_EQ(v.participant("fluid")->options["grid"]["cells"][2].as<int>(), 20 << level);
  }
  EXPECT_EQ(doc["coupling"]["window"].as<double>(), 0.01);  // the scene itself is left as it was
}

const char* kGas = R"(time: {end: 2.0e-4}
coupling: {window: 2.0e-5, scheme: serial-explicit}
domain: {min: [0, 0, 0], max: [2.0e-5, 1.0e-3, 2.0e-5]}
effects: [rarefied_gas]
participants:
  tracker:
    dt: 5.0e-8
    options:
      mesh: {type: box, cells: [1, 50, 1], periodic: [true, false, true]}
      particles: {total: 5000, temperature: 273, mass: 6.63e-26, weight: 1.0e6}
)";

const Varied* find_key(const std::vector<Varied>& keys, const std::string& key) {
  const auto it = std::find_if(keys.begin(), keys.end(), [&](const Varied& v) { return v.key == key; });
  return it == keys.end() ? nullptr : &*it;
}

// The value `key` takes on `level` (0-based) as text, or "not varied".
std::string value_at(const std::vector<Varied>& keys, const std::string& key, std::size_t level) {
  const Varied* v = find_key(keys, key);
  return v == nullptr ? "not varied" : text(v->values.at(level));
}

// The tracker's cells refine as a fluid grid's do, and its particles grow with them, each
// standing for fewer molecules, so that the gas stays the same.
TEST(Refine, TheTrackersCellsAndParticlesGrowTogether) {
  const std::vector<Varied> keys = refine(scene::load_scene_from_string(kGas), 2, 3);
  EXPECT_EQ(value_at(keys, "participants.tracker.options.mesh.cells", 2),
            "[1, 200, 1]");  // the periodic single layers stay one cell
  EXPECT_EQ(value_at(keys, "participants.tracker.options.particles.total", 1), "10000");
  EXPECT_EQ(value_at(keys, "participants.tracker.options.particles.total", 2), "20000");
  EXPECT_EQ(value_at(keys, "participants.tracker.options.particles.weight", 2), "250000");

  // Particles written every other field frame stay so.
  std::string written = kGas;
  written.replace(written.find("domain:"), 0, "output: {fields_every: 5}\n");
  written.replace(written.find("      particles:"), 0, "      particle_output: {every: 10}\n");
  const auto frames = refine(scene::load_scene_from_string(written), 2, 3);
  EXPECT_EQ(value_at(frames, "participants.tracker.options.particle_output.every", 2), "40");
  EXPECT_EQ(value_at(frames, "output.fields_every", 2), "20");

  // Gas by region: as many real molecules, each simulator standing for fewer of them.
  std::string regions = kGas;
  regions.replace(regions.find("total: 5000"), 11, "regions: [{number_density: 1.0e20}]");
  const auto by_region = refine(scene::load_scene_from_string(regions), 2, 2);
  EXPECT_EQ(value_at(by_region, "participants.tracker.options.particles.weight", 1), "500000");
  EXPECT_EQ(value_at(by_region, "participants.tracker.options.particles.total", 0), "not varied");

  // Particles per cell are kept as they are; a Voronoi mesh's seeds grow as the cube, and so
  // do its particles.
  std::string voronoi = kGas;
  voronoi.replace(voronoi.find("{type: box, cells: [1, 50, 1], periodic: [true, false, true]}"), 61,
                  "{type: voronoi, points: 1000}");
  voronoi.replace(voronoi.find("total: 5000"), 11, "per_cell: 20");
  const auto seeded = refine(scene::load_scene_from_string(voronoi), 2, 2);
  EXPECT_EQ(value_at(seeded, "participants.tracker.options.mesh.points", 1), "8000");
  EXPECT_EQ(value_at(seeded, "participants.tracker.options.particles.per_cell", 0), "not varied");
  EXPECT_EQ(value_at(seeded, "participants.tracker.options.particles.weight", 1), "125000");
}

// A tolerance the scene writes shrinks as the square of the scale; one it leaves to its
// default stays the program's.
TEST(Refine, WrittenTolerancesShrinkAsTheSquareOfTheScale) {
  std::string yaml = kScene;
  yaml.replace(yaml.find("coupling: {window: 0.01}"), 24, "coupling: {window: 0.01, tolerance: 1.0e-4}");
  yaml.replace(yaml.find("options: {grid"), 14, "options: {bodies: {tolerance: 1.0e-5}, grid");
  const std::vector<Varied> keys = refine(scene::load_scene_from_string(yaml), 2, 3);
  EXPECT_EQ(value_at(keys, "coupling.tolerance", 0), "0.0001");
  EXPECT_EQ(value_at(keys, "coupling.tolerance", 2), "6.25e-06");
  EXPECT_EQ(value_at(keys, "participants.fluid.options.bodies.tolerance", 1), "2.5e-06");
  EXPECT_EQ(value_at(keys, "participants.rigidbody.options.tolerance", 0), "not varied");
  const YAML::Node doc = YAML::Load(yaml);
  YAML::Emitter out;
  out << variant(doc, keys, 2);
  EXPECT_DOUBLE_EQ(scene::load_scene_from_string(out.c_str()).coupling.tolerance, 6.25e-6);
  // Levels coarser than the scene (--target's) keep what it asks, and none goes below
  // round-off's.
  const auto coarse = scaled(scene::load_scene_from_string(yaml), {0.5, 1, 1e5}, "--target x=1%");
  EXPECT_EQ(value_at(coarse, "coupling.tolerance", 0), "0.0001");
  EXPECT_EQ(value_at(coarse, "coupling.tolerance", 2), "1e-12");
  // An explicit scheme does not iterate: its coupling tolerance is read by nothing.
  yaml.replace(yaml.find("tolerance: 1.0e-4}"), 18, "tolerance: 1.0e-4, scheme: serial-explicit}");
  EXPECT_EQ(find_key(refine(scene::load_scene_from_string(yaml), 2, 2), "coupling.tolerance"), nullptr);
}

// A scale that is not a whole ratio keeps time.end a whole number of windows and each
// window the same whole number of steps; the fluid's first step shrinks with them.
TEST(Scaled, AnyScaleGivesWholeWindowsAndStepsPerWindow) {
  std::string yaml = kScene;
  yaml.replace(yaml.find("options: {grid"), 14, "options: {dt_initial: 0.005, grid");
  const scene::Scene s = scene::load_scene_from_string(yaml);
  const std::vector<Varied> keys = scaled(s, {1 / 2.25, 1 / 1.5, 1, 2.3}, "--target x=1%");
  ASSERT_EQ(keys.size(), 5u);
  EXPECT_EQ(keys[3].key, "participants.fluid.options.dt_initial");
  const std::vector<double> scales = scales_of(s, keys), expected{0.44, 0.67, 1, 2.3};
  for (std::size_t k = 0; k < 4; ++k) EXPECT_NEAR(scales[k], expected[k], 1e-12) << k;
  const YAML::Node doc = YAML::Load(s.text);
  for (std::size_t level = 0; level < 4; ++level) {
    YAML::Emitter out;
    out << variant(doc, keys, level);
    const scene::Scene v = scene::load_scene_from_string(out.c_str());  // throws if not whole
    EXPECT_NEAR(v.coupling.window / v.participant("rigidbody")->dt, 10, 1e-9);
    EXPECT_NEAR(v.participant("fluid")->options["dt_initial"].as<double>(), v.coupling.window / 2, 1e-15);
  }
  EXPECT_EQ(text(keys[4].values[0]), "[4, 4, 9]");
  EXPECT_EQ(text(keys[4].values[3]), "[23, 23, 46]");
  // A two-dimensional scene's single layer stays one cell.
  std::string flat = kScene;
  flat.replace(flat.find("[10, 10, 20]"), 12, "[10, 20, 1]");
  const auto layer = scaled(scene::load_scene_from_string(flat), {2.3}, "--target x=1%");
  EXPECT_EQ(text(layer.back().values[0]), "[23, 46, 1]");
}

// A scene that writes fields every N windows writes them at the same times on every level.
TEST(Scaled, FieldFramesKeepTheirTimes) {
  std::string yaml = kScene;
  yaml.replace(yaml.find("domain:"), 0, "output: {fields_every: 5}\n");
  const scene::Scene s = scene::load_scene_from_string(yaml);
  const std::vector<Varied> keys = scaled(s, {1 / 2.25, 0.5, 1, 2}, "--target x=1%");
  const auto frames =
      std::find_if(keys.begin(), keys.end(), [](const Varied& v) { return v.key == "output.fields_every"; });
  ASSERT_NE(frames, keys.end());
  EXPECT_EQ(text(frames->values[0]), "2");  // 44 windows: every 2.2, rounded
  EXPECT_EQ(text(frames->values[1]), "3");  // 50 windows: every 2.5, rounded away from zero
  EXPECT_EQ(text(frames->values[2]), "5");
  EXPECT_EQ(text(frames->values[3]), "10");
  // Without the key in the scene nothing is added (the default's frames are the scene's).
  for (const Varied& v : scaled(scene::load_scene_from_string(kScene), {0.5, 1}, "x"))
    EXPECT_NE(v.key, "output.fields_every");
}

TEST(Ratios, StepsShrinkAndCountsGrow) {
  EXPECT_EQ(refinement_ratios(parse_vary("w=0.01,0.005,0.002")).r, (std::vector<double>{2, 2.5}));
  const Ratios cells = refinement_ratios(parse_vary("c=[10,10,10],[20,20,20],[40,40,80]"));
  ASSERT_EQ(cells.r.size(), 2u);
  EXPECT_DOUBLE_EQ(cells.r[0], 2);
  EXPECT_DOUBLE_EQ(cells.r[1], std::cbrt(16.0));  // (2 x 2 x 4)^(1/3)
  // Axes no level refines (a two-dimensional grid's single layer, a channel's periodic
  // directions) do not count: the ratio is that of the axes refined.
  const Ratios plane = refinement_ratios(parse_vary("c=[110,21,1],[220,42,1],[440,84,1]"));
  ASSERT_EQ(plane.r.size(), 2u);
  EXPECT_NEAR(plane.r[0], 2, 1e-12);
  EXPECT_NEAR(plane.r[1], 2, 1e-12);
  const Ratios channel = refinement_ratios(parse_vary("c=[4,8,4],[4,16,4],[4,40,4]"));
  ASSERT_EQ(channel.r.size(), 2u);
  EXPECT_NEAR(channel.r[0], 2, 1e-12);
  EXPECT_NEAR(channel.r[1], 2.5, 1e-12);
  EXPECT_EQ(refinement_ratios(parse_vary("s=iqn-ils,aitken")).why_none,
            "the values of s are not positive numbers (or lists of them of one length)");
  EXPECT_FALSE(refinement_ratios(parse_vary("c=[4,8],[4,8,16]")).why_none.empty());
  EXPECT_EQ(refinement_ratios(parse_vary("w=0.01,0.005,0.01")).why_none,
            "the values of w neither all grow nor all shrink from level to level");
}

}  // namespace
}  // namespace cosim::study
