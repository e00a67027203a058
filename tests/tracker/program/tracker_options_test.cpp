// The tracker's own options (walls, obstacles, particles, particle output): every mistake
// names file, line, key and value, and a good section reads into the conditions the
// tracking uses.
#include <gtest/gtest.h>

#include <optional>
#include <utility>

#include "coupler/scene/error.hpp"
#include "tracker/program/scene_tracker.hpp"

#include "tests/tracker/program/scene_error.hpp"

namespace cosim::tracker::program {
namespace {

constexpr const char* kParticles = "      particles: {per_cell: 2, temperature: 1, mass: 1}\n";

scene::Scene scene_with(const std::string& options, const std::string& mesh = "{type: box, cells: [2, 2, 2]}") {
  return scene::load_scene_from_string(
      "time: {end: 0.1}\ncoupling: {window: 0.1}\ndomain: {min: [0, 0, 0], max: [1, 1, 1]}\n"
      "effects: [rarefied_gas]\nparticipants:\n  tracker:\n    dt: 0.01\n    options:\n"
      "      mesh: " +
          mesh + "\n" + options,
      "scene.yaml");
}

std::string error_of(const std::string& options, const std::string& mesh = "{type: box, cells: [2, 2, 2]}") {
  return testing::scene_error_of([&] { read_tracker(scene_with(options, mesh)); });
}

#define EXPECT_ERROR(options, text) EXPECT_NE(error_of(options).find(text), std::string::npos) << error_of(options)

TEST(TrackerOptions, ReadsWallsObstaclesAndParticles) {
  const TrackerScene t = read_tracker(
      scene_with(std::string(kParticles) +
                 "      boundaries:\n        default: {kind: maxwell, temperature: 300, accommodation: 0.5}\n"
                 "        x_max: {kind: open}\n"
                 "      obstacles:\n"
                 "        - {name: ball, shape: {ball: {centre: [0.5, 0.5, 0.5], radius: 0.2}}, wall: {kind: diffuse, "
                 "temperature: 10}}\n"
                 "        - {name: zone, shape: {box: {centre: [0.2, 0.2, 0.2], half_extents: [0.1, 0.1, 0.1]}}, "
                 "permeable: true}\n"));
  ASSERT_EQ(t.domain->boundaries.patches.size(), 6u);
  EXPECT_EQ(t.domain->boundaries.patches[0].kind, tracking::BoundaryKind::maxwell);
  EXPECT_EQ(t.domain->boundaries.patches[0].accommodation, 0.5);
  EXPECT_EQ(t.domain->boundaries.patches[1].kind, tracking::BoundaryKind::open);
  EXPECT_EQ(t.domain->boundaries.mass, 1.0);
  ASSERT_EQ(t.obstacles.count(), 2);
  EXPECT_EQ(t.obstacles.object(0).wall.kind, tracking::BoundaryKind::diffuse);
  EXPECT_EQ(t.obstacles.object(0).wall.temperature, 10.0);
  EXPECT_TRUE(t.obstacles.object(1).permeable);
  EXPECT_EQ(t.particles.per_cell, 2);
  EXPECT_EQ(t.dt, 0.01);
}

TEST(TrackerOptions, WallMistakesNameTheKey) {
  const std::string p = kParticles;
  EXPECT_ERROR(p, "no condition for patch x_min");
  EXPECT_ERROR(p + "      boundaries: {default: {kind: specular}, x_mn: {kind: open}}\n",
               "participants.tracker.options.boundaries.x_mn");
  EXPECT_ERROR(p + "      boundaries: {default: {kind: sticky}}\n", "boundaries.default.kind = sticky");
  EXPECT_ERROR(p + "      boundaries: {default: {kind: diffuse}}\n", "boundaries.default.temperature");
  EXPECT_ERROR(p + "      boundaries: {default: {kind: diffuse, temperature: -3}}\n", "temperature = -3");
  EXPECT_ERROR(p + "      boundaries: {default: {kind: maxwell, temperature: 3, accommodation: 1.5}}\n",
               "accommodation = 1.5");
  EXPECT_ERROR(p + "      boundaries: {default: {kind: specular, temperature: 3}}\n", "default.temperature");
  EXPECT_ERROR(p + "      boundaries: {default: {kind: specular}, y_min: {kind: periodic}}\n",
               "boundaries.y_min = {kind: periodic}: the mesh does not link");
  const std::string periodic_x = "{type: box, cells: [2, 2, 2], periodic: [true, false, false]}";
  EXPECT_NE(error_of(p + "      boundaries: {default: {kind: specular}, x_max: {kind: open}}\n", periodic_x)
                .find("boundaries.x_max = {kind: open}: the mesh links this patch periodically"),
            std::string::npos);
  EXPECT_EQ(error_of(p + "      boundaries: {default: {kind: specular}, x_max: {kind: periodic}}\n", periodic_x),
            "no error");
}

TEST(TrackerOptions, MovingWallsTakeAVelocityOnlyWhereTheyReEmit) {
  const std::string p = std::string(kParticles) + "      boundaries:\n        default: {kind: specular}\n";
  const TrackerScene t =
      read_tracker(scene_with(p + "        y_max: {kind: diffuse, temperature: 300, velocity: [50, 0, -2]}\n"
                                  "        y_min: {kind: maxwell, temperature: 300, accommodation: 0.5}\n"));
  EXPECT_EQ(t.domain->boundaries.patches[3].velocity, Vec3(50, 0, -2));
  EXPECT_EQ(t.domain->boundaries.patches[2].velocity, Vec3::Zero());
  EXPECT_ERROR(p + "        y_max: {kind: specular, velocity: [50, 0, 0]}\n",
               "boundaries.y_max.velocity = [50, 0, 0]: only diffuse and maxwell walls move");
  EXPECT_ERROR(p + "        y_max: {kind: open, velocity: [1, 0, 0]}\n", "boundaries.y_max.velocity");
  EXPECT_ERROR(p + "        y_max: {kind: diffuse, temperature: 300, velocity: [50, 0]}\n",
               "boundaries.y_max.velocity");
}

TEST(TrackerOptions, ObstacleMistakesNameTheKey) {
  const std::string p = std::string(kParticles) + "      boundaries: {default: {kind: specular}}\n      obstacles:\n";
  const std::string ball = "shape: {ball: {centre: [0.5, 0.5, 0.5], radius: 0.2}}";
  EXPECT_ERROR(p + "        - {name: a, " + ball + ", wall: {kind: periodic}}\n", "obstacles[0].wall.kind = periodic");
  EXPECT_ERROR(p + "        - {name: a, " + ball + ", permeable: true, wall: {kind: open}}\n", "obstacles[0].wall");
  EXPECT_ERROR(p + "        - {name: a, " + ball + "}\n        - {name: a, " + ball + "}\n", "obstacles[1].name = a");
  EXPECT_ERROR(p + "        - {name: a, shape: {ball: {centre: [0.5, 0.5, 0.5], radius: -1}}}\n",
               "obstacles[0].shape.ball.radius = -1");
  EXPECT_ERROR(p + "        - {name: a, " + ball + ", permeable: maybe}\n", "obstacles[0].permeable = maybe");
  // In millimetres in a metre-sized domain: far outside, and said so.
  EXPECT_ERROR(p + "        - {name: far, shape: {ball: {centre: [500, 500, 500], radius: 200}}}\n",
               "obstacle 'far': its surface meets no cell of the mesh");
}

TEST(TrackerOptions, RegionsReadIntoTheirStates) {
  const TrackerScene t = read_tracker(scene_with(
      "      boundaries: {default: {kind: specular}}\n"
      "      particles:\n        mass: 2\n        weight: 3\n        regions:\n"
      "          - {region: {ball: {centre: [0.5, 0.5, 0.5], radius: 0.2}}, number_density: 10, temperature: 4,"
      " velocity: [1, 2, 3]}\n"
      "          - {region: {box: {centre: [0.5, 0.5, 0.5], half_extents: [0.5, 0.5, 0.5]}}, number_density: 5,"
      " temperature: 0}\n"));
  ASSERT_EQ(t.particles.regions.size(), 2u);
  EXPECT_EQ(t.particles.regions[0].number_density, 10);
  EXPECT_EQ(t.particles.regions[0].temperature, 4);
  EXPECT_EQ(t.particles.regions[0].velocity, Vec3(1, 2, 3));
  EXPECT_EQ(t.particles.regions[1].velocity, Vec3::Zero());
  EXPECT_EQ(t.particles.weight, 3);
  EXPECT_EQ(t.particles.hottest(), 4);
  EXPECT_EQ(t.particles.fastest_drift(), Vec3(1, 2, 3).norm());
}

TEST(TrackerOptions, RegionMistakesNameTheKey) {
  const std::string p = "      boundaries: {default: {kind: specular}}\n      particles:\n        mass: 1\n";
  const std::string ball = "{ball: {centre: [0.5, 0.5, 0.5], radius: 0.2}}";
  const auto region = [&](const std::string& rest) {
    return p + "        regions:\n          - {region: " + ball + ", " + rest + "}\n";
  };
  EXPECT_ERROR(region("number_density: 0, temperature: 1"),
               "scene.yaml:14: participants.tracker.options.particles."
               "regions[0].number_density = 0: must be > 0");
  EXPECT_ERROR(region("number_density: 1, temperature: -1"), "particles.regions[0].temperature = -1");
  EXPECT_ERROR(region("number_density: 1"), "particles.regions[0].temperature");
  EXPECT_ERROR(region("number_density: 1, temperature: 1, velocity: [1, 2]"), "particles.regions[0].velocity");
  EXPECT_ERROR(region("number_density: 1, temperature: 1, species: {Ar: 0.5, He: 0.5}"),
               "particles.regions[0].species = {Ar: 0.5, He: 0.5}: the gas is one species");
  EXPECT_ERROR(region("number_density: 1, temperature: 1, drift: [1, 0, 0]"),
               "particles.regions[0].drift = [1, 0, 0]: unknown key");
  EXPECT_ERROR(p + "        regions:\n          - {region: {sphere: {radius: 1}}, number_density: 1, temperature: 1}\n",
               "particles.regions[0].region.sphere = {radius: 1}: unknown shape");
  EXPECT_ERROR(p + "        regions:\n          - {number_density: 1, temperature: 1}\n",
               "particles.regions[0].region");
  EXPECT_ERROR(p + "        regions: []\n", "particles.regions = []: needs at least one region");
  EXPECT_ERROR(p + "        per_cell: 2\n        regions:\n          - {region: " + ball +
                   ", number_density: 1, temperature: 1}\n",
               "particles.per_cell = 2: not with regions");
  // A real density with the default weight 1: 2.5e25 in the unit box is far too many.
  EXPECT_ERROR(region("number_density: 2.5e25, temperature: 300"),
               "particles.regions[0].number_density = 2.5e25: up to 2.5e+25 particles in the mesh's 1 m^3 at "
               "particles.weight 1: give a weight");
}

TEST(TrackerOptions, InflowMistakesNameTheKey) {
  const std::string p =
      std::string(kParticles) + "      boundaries: {default: {kind: specular}, x_min: {kind: open}}\n";
  EXPECT_ERROR(p + "      inflow: [{patches: [y_min], number_density: 1, temperature: 1}]\n",
               "inflow[0].patches = [y_min]: patch y_min is not open");
  EXPECT_ERROR(p + "      inflow: [{patches: [x_mn], number_density: 1, temperature: 1}]\n", "inflow[0].patches");
  EXPECT_ERROR(p + "      inflow: [{patches: [x_min], number_density: 0, temperature: 1}]\n",
               "inflow[0].number_density = 0");
  EXPECT_ERROR(p + "      inflow: [{patches: [x_min], number_density: 1, temperature: 1, speed: 3}]\n",
               "inflow[0].speed = 3: unknown key");
  const TrackerScene t =
      read_tracker(scene_with(p + "      inflow: [{patches: [x_min], number_density: 2, temperature: 1}]\n"));
  ASSERT_EQ(t.inflows.size(), 1u);
  EXPECT_GT(t.inflows[0].rate(), 0.0);
}

TEST(TrackerOptions, ParticleMistakesNameTheKey) {
  const std::string walls = "      boundaries: {default: {kind: specular}}\n";
  EXPECT_ERROR(walls, "participants.tracker.options.particles");
  EXPECT_ERROR(walls + "      particles: {per_cell: 2, total: 9, temperature: 1, mass: 1}\n", "exactly one of");
  EXPECT_ERROR(walls + "      particles: {per_cell: 2.5, temperature: 1, mass: 1}\n", "particles.per_cell = 2.5");
  EXPECT_ERROR(walls + "      particles: {total: 9, temperature: 1, mass: -1}\n", "particles.mass = -1");
  EXPECT_ERROR(walls + "      particles: {total: 9, temperature: 1, mass: 1, drift: [1, 2]}\n", "particles.drift");
  EXPECT_ERROR(walls + "      particles: {total: 9, temperature: 1, mass: 1, colour: red}\n",
               "particles.colour = red: unknown key");
  EXPECT_ERROR(walls + kParticles + "      velocity: 3\n", "options.velocity = 3: unknown key");
  EXPECT_ERROR(walls + kParticles + "      balance: {every: -1}\n", "balance.every = -1");
  EXPECT_ERROR(walls + kParticles + "      balance: {threshold: 0.9}\n", "balance.threshold = 0.9");
  EXPECT_ERROR(walls + kParticles + "      balance: {often: 3}\n", "balance.often = 3: unknown key");
  EXPECT_ERROR(
      walls +
          "      particles: {total: 9, temperature: 1, mass: 1.0e-25}\n      collisions: {species: Ar, model: vss}\n",
      "collisions.species = Ar: the particles' mass 1e-25 kg is not Ar's 6.63");
}

TEST(TrackerOptions, ParticleOutputDefaultsToEveryFieldWriteOfAllParticles) {
  const std::string p = std::string(kParticles) + "      boundaries: {default: {kind: specular}}\n";
  EXPECT_FALSE(read_tracker(scene_with(p)).particle_output);
  const std::optional<ParticleOutput> all = read_tracker(scene_with(p + "      particle_output: {}\n")).particle_output;
  ASSERT_TRUE(all);
  EXPECT_EQ(all->every, 10);  // output.fields_every's default
  EXPECT_EQ(all->fraction, 1.0);
  EXPECT_EQ(all->seed, 0u);
  const std::optional<ParticleOutput> some =
      read_tracker(scene_with(p + "      particle_output: {every: 20, fraction: 0.25, seed: 3}\n")).particle_output;
  ASSERT_TRUE(some);
  EXPECT_EQ(some->every, 20);
  EXPECT_EQ(some->fraction, 0.25);
  EXPECT_EQ(some->seed, 3u);
  // The start, every 20th window and the last, as the fields.
  for (const auto& [done, written] :
       {std::pair{0, true}, std::pair{10, false}, std::pair{20, true}, std::pair{35, true}, std::pair{34, false}})
    EXPECT_EQ(some->at(static_cast<std::uint64_t>(done), 35), written) << done;
}

TEST(TrackerOptions, ParticleOutputMistakesNameTheKey) {
  const std::string p = std::string(kParticles) + "      boundaries: {default: {kind: specular}}\n";
  EXPECT_EQ(error_of(p + "      particle_output: {every: 15}\n"),
            "scene.yaml:12: participants.tracker.options.particle_output.every = 15: particles are written with the "
            "fields: give a multiple of output.fields_every (10)");
  EXPECT_ERROR(p + "      particle_output: {every: 0}\n", "particle_output.every = 0: must be");
  EXPECT_ERROR(p + "      particle_output: {fraction: 0}\n", "particle_output.fraction = 0: must be in (0, 1]");
  EXPECT_ERROR(p + "      particle_output: {fraction: 1.5}\n", "particle_output.fraction = 1.5: must be in (0, 1]");
  EXPECT_ERROR(p + "      particle_output: {seed: -1}\n", "particle_output.seed = -1");
  EXPECT_ERROR(p + "      particle_output: {every: 10, sample: 3}\n", "particle_output.sample = 3: unknown key");
  EXPECT_ERROR(p + "      particle_output: 10\n", "particle_output = 10");
  EXPECT_ERROR(p + "      particle_output: {}\n      obstacles:\n"
                   "        - {name: a/b, shape: {ball: {centre: [0.5, 0.5, 0.5], radius: 0.2}}}\n",
               "particle_output = {}: obstacle 'a/b' cannot name the particles' attribute state_a/b");
  // No fields, no particles: refused rather than never written.
  const std::string none = testing::scene_error_of([&] {
    read_tracker(scene::load_scene_from_string(
        "time: {end: 0.1}\ncoupling: {window: 0.1}\noutput: {fields_every: 0}\n"
        "domain: {min: [0, 0, 0], max: [1, 1, 1]}\neffects: [rarefied_gas]\nparticipants:\n  tracker:\n    dt: 0.01\n"
        "    options:\n      mesh: {type: box, cells: [2, 2, 2]}\n" +
            p + "      particle_output: {every: 1}\n",
        "scene.yaml"));
  });
  EXPECT_NE(none.find("participants.tracker.options.particle_output = {every: 1}: particles are written with the "
                      "fields, and output.fields_every is 0"),
            std::string::npos)
      << none;
}

}  // namespace
}  // namespace cosim::tracker::program
