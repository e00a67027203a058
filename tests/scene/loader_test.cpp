#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "tests/scene/errors.hpp"
#include "coupler/scene/plan.hpp"
#include "coupler/scene/reader.hpp"

namespace cosim::scene {
namespace {

const std::filesystem::path data = COSIM_SCENE_TEST_DATA;

TEST(LoadScene, ReadsEveryKeyOfAFullScene) {
  const Scene s = load_scene(data / "full.yaml");
  std::ifstream in(data / "full.yaml");
  std::ostringstream text;
  text << in.rdbuf();
  EXPECT_EQ(s.text, text.str());
  EXPECT_EQ(s.file, data / "full.yaml");

  EXPECT_EQ(s.time.end, 2.0);
  EXPECT_EQ(s.coupling.window, 0.01);
  EXPECT_EQ(s.coupling.scheme, Scheme::ParallelImplicit);
  EXPECT_EQ(s.coupling.acceleration, Acceleration::Aitken);
  EXPECT_EQ(s.coupling.relaxation, 0.25);
  EXPECT_EQ(s.coupling.max_iterations, 30);
  EXPECT_EQ(s.coupling.tolerance, 1e-8);
  EXPECT_EQ(s.coupling.transport, Transport::Tcp);
  EXPECT_EQ(s.coupling.interface, "ib0");
  EXPECT_EQ(s.coupling.timeout, 120.0);
  EXPECT_EQ(s.coupling.heartbeat, 4.0);
  EXPECT_EQ(s.windows(), 200u);
  EXPECT_EQ(s.output.file, "out/run.h5");
  EXPECT_EQ(s.output.every, 2);
  EXPECT_EQ(s.output.checkpoint_every, 20);
  EXPECT_EQ(s.output.fields_every, 5);
  EXPECT_EQ(s.gravity, (Vec3{0, -9.81, 0}));
  EXPECT_EQ(s.domain.min, (Vec3{0, 0, 0}));
  EXPECT_EQ(s.domain.max, (Vec3{1, 1, 2}));

  ASSERT_EQ(s.bodies.size(), 38u);
  const Body& ball = s.bodies[0];
  EXPECT_EQ(ball.name, "ball");
  EXPECT_EQ(ball.shape.type, ShapeType::Sphere);
  EXPECT_EQ(ball.shape.radius, 0.01);
  EXPECT_EQ(ball.material.density, 1120);
  EXPECT_EQ(ball.material.restitution, 0.5);
  EXPECT_EQ(ball.material.friction, 0.3);
  EXPECT_FALSE(ball.fixed);
  EXPECT_EQ(ball.position, (Vec3{0.5, 0.5, 1.5}));
  EXPECT_EQ(ball.orientation, (Quat{0, 0, 0, 1}));
  EXPECT_EQ(ball.velocity, (Vec3{0, 0, -0.1}));
  EXPECT_EQ(ball.angular_velocity, (Vec3{0, 1, 0}));
  EXPECT_EQ(s.bodies[1].shape.type, ShapeType::Ellipsoid);
  EXPECT_EQ(s.bodies[1].shape.radii, (Vec3{0.01, 0.02, 0.03}));
  EXPECT_EQ(s.bodies[1].orientation, (Quat{1, 0, 0, 0}));
  EXPECT_EQ(s.bodies[2].shape.type, ShapeType::Box);
  EXPECT_EQ(s.bodies[2].shape.half_extents, (Vec3{0.05, 0.02, 0.01}));
  EXPECT_EQ(s.bodies[3].shape.type, ShapeType::Cylinder);
  EXPECT_EQ(s.bodies[3].shape.radius, 0.005);
  EXPECT_EQ(s.bodies[3].shape.height, 0.1);
  EXPECT_EQ(s.bodies[4].shape.type, ShapeType::Capsule);
  EXPECT_EQ(s.bodies[4].shape.height, 0.02);
  const Body& floor = s.bodies[5];
  EXPECT_EQ(floor.shape.type, ShapeType::Plane);
  EXPECT_EQ(floor.shape.normal, (Vec3{0, 0, 1}));
  EXPECT_TRUE(floor.fixed);
  EXPECT_EQ(floor.material.density, 0.0);
  const Body& rock = s.bodies[6];
  EXPECT_EQ(rock.shape.type, ShapeType::Mesh);
  EXPECT_EQ(rock.shape.file, data / "cube.obj");
  EXPECT_EQ(rock.material.density, 2600);
  EXPECT_EQ(rock.material.friction, 0.6);
  // Generated: 3 x 3 x 2 grains, 10 beans (solid fraction 0.001 of 0.1 m^3), 3 pebbles.
  ASSERT_EQ(s.generators.size(), 3u);
  const auto made = [&](std::size_t g) { return std::pair(s.generators[g].first, s.generators[g].count); };
  EXPECT_EQ(s.generators[0].entry, 7u);
  EXPECT_EQ(s.generators[0].kind, Generator::Lattice);
  EXPECT_EQ(made(0), std::pair(std::size_t{7}, std::size_t{18}));
  EXPECT_EQ(s.generators[1].kind, Generator::Random);
  EXPECT_EQ(made(1), std::pair(std::size_t{25}, std::size_t{10}));
  EXPECT_EQ(s.generators[2].kind, Generator::File);
  EXPECT_EQ(made(2), std::pair(std::size_t{35}, std::size_t{3}));
  EXPECT_EQ(s.bodies[7].name, "grain00");
  EXPECT_EQ(s.bodies[24].name, "grain17");
  EXPECT_NEAR(s.bodies[24].position[2], 1.75, 1e-12);  // unjittered in z: 1.7 +- 0.05
  EXPECT_EQ(s.bodies[34].name, "bean9");
  EXPECT_TRUE(s.bodies[34].fixed);
  const Body& pebble = s.bodies[37];
  EXPECT_EQ(pebble.name, "pebble2");
  EXPECT_EQ(pebble.position, (Vec3{0.6, 0.2, 0.6}));
  EXPECT_EQ(pebble.orientation, (Quat{0, 1, 0, 0}));
  EXPECT_EQ(pebble.velocity, (Vec3{0, 0, -0.5}));
  EXPECT_EQ(pebble.angular_velocity, (Vec3{1, 0, 0}));

  EXPECT_EQ(s.effects, (std::vector<Effect>{Effect::Gravity, Effect::Buoyancy, Effect::Hydrodynamics, Effect::Contact,
                                            Effect::Friction}));
  EXPECT_EQ(s.effects_line, 75);
  EXPECT_TRUE(s.has_effect(Effect::Contact));
  EXPECT_FALSE(s.has_effect(Effect::Tracers));

  ASSERT_EQ(s.participants.size(), 3u);
  const Participant& rigid = s.participants[0];
  EXPECT_EQ(rigid.name, "rigidbody");
  EXPECT_TRUE(rigid.command.empty());
  EXPECT_EQ(rigid.ranks, 1);
  EXPECT_EQ(rigid.dt, 1e-4);
  EXPECT_EQ(rigid.line, 77);
  EXPECT_EQ(rigid.options["iterations"].as<int>(), 20);
  const Participant* fluid = s.participant("fluid");
  ASSERT_NE(fluid, nullptr);
  EXPECT_EQ(fluid->command, (std::vector<std::string>{"cosim-fluid", "--verbose"}));
  EXPECT_EQ(fluid->ranks, 4);
  EXPECT_TRUE(fluid->options.IsMap());
  EXPECT_EQ(fluid->options.size(), 0u);
  const Participant* spring = s.participant("spring");
  ASSERT_NE(spring, nullptr);
  EXPECT_EQ(spring->command, (std::vector<std::string>{"spring-model", "--stiffness", "100"}));
  EXPECT_EQ(spring->dt, 5e-3);
  EXPECT_EQ(spring->provides, static_cast<DataSet>(Data::Forces));
  EXPECT_EQ(spring->needs, static_cast<DataSet>(Data::Poses));
  EXPECT_EQ(s.participant("tracker"), nullptr);

  ASSERT_EQ(s.study.measures.size(), 2u);
  EXPECT_EQ(s.study.measures[0].name, "top");
  EXPECT_EQ(s.study.measures[0].expression, "max(body:ball:position.z)");
  EXPECT_EQ(s.study.measures[0].line, 91);
  EXPECT_EQ(s.study.measures[1].name, "drift");
  EXPECT_EQ(s.study.measures[1].expression, "mean(body:ball:velocity.x, 0.5, 1.5)");
  EXPECT_EQ(s.study.order, 2.0);
}

TEST(LoadScene, AppliesDefaults) {
  const Scene s = load_scene_from_string(head +
                                         "bodies: [{name: b, position: [0.5, 0.5, 0.5], material: {density: 1},"
                                         " shape: {type: sphere, radius: 0.1}}]\n");
  EXPECT_EQ(s.file, "<string>");
  EXPECT_EQ(s.coupling.scheme, Scheme::SerialImplicit);
  EXPECT_EQ(s.coupling.acceleration, Acceleration::IqnIls);
  EXPECT_EQ(s.coupling.relaxation, 0.5);
  EXPECT_EQ(s.coupling.max_iterations, 50);
  EXPECT_EQ(s.coupling.tolerance, 1e-6);
  EXPECT_EQ(s.coupling.transport, Transport::Ipc);
  EXPECT_EQ(s.coupling.timeout, 60.0);
  EXPECT_EQ(s.output.file, "run.h5");
  EXPECT_EQ(s.output.every, 1);
  EXPECT_EQ(s.output.checkpoint_every, 10);
  EXPECT_EQ(s.output.fields_every, 10);
  EXPECT_EQ(s.gravity, (Vec3{0, 0, -9.81}));
  const Body& b = s.bodies.at(0);
  EXPECT_FALSE(b.fixed);
  EXPECT_EQ(b.orientation, (Quat{1, 0, 0, 0}));
  EXPECT_EQ(b.velocity, (Vec3{0, 0, 0}));
  EXPECT_EQ(b.angular_velocity, (Vec3{0, 0, 0}));
  EXPECT_EQ(b.material.restitution, 0.0);
  EXPECT_EQ(b.material.friction, 0.0);
  EXPECT_TRUE(s.effects.empty());
  EXPECT_TRUE(s.participants.empty());
  EXPECT_TRUE(s.study.measures.empty());
  EXPECT_FALSE(s.study.order);
  EXPECT_EQ(s.windows(), 100u);
}

TEST(LoadScene, WindowsAreExactDespiteRounding) {
  const Scene s =
      load_scene_from_string("time: {end: 0.3}\ncoupling: {window: 0.1}\ndomain: {min: [0, 0, 0], max: [1, 1, 1]}\n");
  EXPECT_EQ(s.windows(), 3u);
}

TEST(LoadScene, NormalisesQuaternionsWithinTolerance) {
  const Scene s = load_scene_from_string(head + R"(bodies:
  - {name: b, position: [0.5, 0.5, 0.5], material: {density: 1}, shape: {type: sphere, radius: 0.1},
     orientation: [0.7071068, 0, 0, 0.7071068]}
)");
  const Quat& q = s.bodies.at(0).orientation;
  EXPECT_NEAR(q[0] * q[0] + q[3] * q[3], 1.0, 1e-15);
}

TEST(LoadScene, ParticipantOptionsAreReadByTheirProgram) {
  const Scene s = load_scene_from_string(head + R"(effects: [tracers]
participants:
  tracker: {dt: 0.01, options: {particles: 1000, sede: 4}}
  fluid: {dt: 0.01}
)",
                                         "scene.yaml");
  const Reader tracker = options_of(s, *s.participant("tracker"));
  EXPECT_EQ(tracker.integer("particles"), 1000);
  EXPECT_EQ(tracker.integer("seed", 1), 1);
  EXPECT_EQ(thrown([&] { tracker.finish(); }),
            "scene.yaml:6: participants.tracker.options.sede = 4: unknown key; expected one of: particles, seed");
  const Reader fluid = options_of(s, *s.participant("fluid"));
  EXPECT_FALSE(fluid.has("anything"));
  EXPECT_NO_THROW(fluid.finish());
}

TEST(LoadScene, NamesUseTheWordsOfTheFile) {
  EXPECT_STREQ(to_string(Scheme::SerialExplicit), "serial-explicit");
  EXPECT_STREQ(to_string(Scheme::ParallelImplicit), "parallel-implicit");
  EXPECT_STREQ(to_string(Acceleration::IqnIls), "iqn-ils");
  EXPECT_STREQ(to_string(Acceleration::None), "none");
  EXPECT_STREQ(to_string(Effect::RarefiedGas), "rarefied_gas");
  EXPECT_STREQ(to_string(Effect::Tracers), "tracers");
}

TEST(LoadScene, FieldsAtTheStartEveryNWindowsAndTheEnd) {
  Output o;
  o.fields_every = 4;
  std::vector<std::uint64_t> at;
  for (std::uint64_t done = 0; done <= 10; ++done)
    if (o.fields_at(done, 10)) at.push_back(done);
  EXPECT_EQ(at, (std::vector<std::uint64_t>{0, 4, 8, 10}));
  o.fields_every = 0;
  EXPECT_FALSE(o.fields_at(0, 10));
  EXPECT_FALSE(o.fields_at(10, 10));
}

}  // namespace
}  // namespace cosim::scene
