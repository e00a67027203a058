// Every way a scene can be wrong, with the exact message the user sees. `head` is lines 1-3.
#include <gtest/gtest.h>

#include "tests/scene/errors.hpp"

namespace {

// A body list entry on one line.
std::string body(const std::string& keys) { return "  - {name: ball, " + keys + "}\n"; }

const std::string sphere = "shape: {type: sphere, radius: 0.1}";

// A valid body, plus `extra` keys.
std::string ball(const std::string& extra = "") {
  return body(sphere + ", material: {density: 1000}, position: [0.5, 0.5, 0.5]" + extra);
}

TEST(Validation, UnknownTopLevelKey) {
  EXPECT_EQ(load_error(head + "bodys: []\n"),
            "scene.yaml:4: bodys = []: unknown key; expected one of: "
            "time, coupling, output, gravity, domain, folder, bodies, effects, participants, study");
}

TEST(Validation, FolderMustExist) {
  EXPECT_EQ(load_error(head + "folder: no-such-folder\n"),
            "scene.yaml:4: folder = no-such-folder: no such folder: no-such-folder");
}

TEST(Validation, UnknownNestedKey) {
  EXPECT_EQ(
      load_error("time: {end: 1}\ncoupling: {window: 0.01, windw: 0.02}\n"
                 "domain: {min: [0, 0, 0], max: [1, 1, 1]}\n"),
      "scene.yaml:2: coupling.windw = 0.02: unknown key; expected one of: "
      "window, scheme, acceleration, relaxation, max_iterations, tolerance, force_tolerance, transport, interface, "
      "timeout, heartbeat");
  EXPECT_EQ(load_error(head + "bodies:\n" + ball(", colour: red")),
            "scene.yaml:5: bodies[0].colour = red: unknown key; expected one of: "
            "generate, name, fixed, shape, material, orientation, velocity, angular_velocity, position");
  EXPECT_EQ(load_error(head + "bodies:\n  - name: ball\n    shape: {type: sphere, radius: 0.1, height: 1}\n"),
            "scene.yaml:6: bodies[0].shape.height = 1: unknown key; expected one of: type, radius, container");
}

// `study` is cosim study's (docs/study.md): the loader checks its shape, not the expressions.
TEST(Validation, StudySection) {
  EXPECT_EQ(load_error(head + "study: {measure: {peak: max(body:b:velocity.z)}, order: 2}\n"), "");
  EXPECT_EQ(load_error(head + "study: {measures: {}}\n"),
            "scene.yaml:4: study.measures = {}: unknown key; expected one of: measure, order");
  EXPECT_EQ(load_error(head + "study:\n  measure:\n    peak speed: max(body:b:velocity.z)\n"),
            "scene.yaml:6: study.measure.peak speed = max(body:b:velocity.z): expected a name of 1 to 31 "
            "letters, digits, '_' and '-'");
  EXPECT_EQ(load_error(head + "study: {measure: {peak: [1, 2]}}\n"),
            "scene.yaml:4: study.measure.peak = [1, 2]: expected a string");
  EXPECT_EQ(load_error(head + "study: {order: 0}\n"), "scene.yaml:4: study.order = 0: must be > 0");
}

TEST(Validation, WrongType) {
  EXPECT_EQ(load_error("time: {end: 1}\ncoupling: {window: short}\ndomain: {min: [0, 0, 0], max: [1, 1, 1]}\n"),
            "scene.yaml:2: coupling.window = short: expected a number");
  EXPECT_EQ(load_error("time: 1\n"), "scene.yaml:1: time = 1: expected a mapping");
  EXPECT_EQ(load_error(head + "gravity: [0, -9.81]\n"),
            "scene.yaml:4: gravity = [0, -9.81]: expected a list of 3 numbers");
  EXPECT_EQ(load_error(head + "output: {every: 2.5}\n"), "scene.yaml:4: output.every = 2.5: expected an integer");
  EXPECT_EQ(load_error(head + "output: {fields_every: -1}\n"), "scene.yaml:4: output.fields_every = -1: must be >= 0");
  EXPECT_EQ(load_error(head + "bodies:\n" + ball(", fixed: maybe")),
            "scene.yaml:5: bodies[0].fixed = maybe: expected true or false");
  EXPECT_EQ(load_error(head + "bodies: {name: ball}\n"),
            "scene.yaml:4: bodies = {name: ball}: expected a list of mappings");
  EXPECT_EQ(load_error(head + "bodies: [ball]\n"), "scene.yaml:4: bodies[0] = ball: expected a mapping");
  EXPECT_EQ(load_error("[time, coupling]\n"), "scene.yaml:1: expected a mapping");
}

TEST(Validation, MissingRequiredField) {
  EXPECT_EQ(load_error("time: {end: 1}\ncoupling: {window: 0.01}\n"), "scene.yaml:1: domain: missing required key");
  EXPECT_EQ(load_error(head + "bodies:\n  - name: ball\n    shape: {type: sphere}\n"),
            "scene.yaml:6: bodies[0].shape.radius: missing required key");
  EXPECT_EQ(load_error(head + "bodies:\n  - name: ball\n    shape: {type: sphere, radius: 0.1}\n"),
            "scene.yaml:5: bodies[0].material: missing required key");
  EXPECT_EQ(load_error(""), "scene.yaml: expected a mapping");
}

TEST(Validation, NegativeDensity) {
  EXPECT_EQ(load_error(head + R"(bodies:
  - name: ball
    shape: {type: sphere, radius: 0.1}
    material: {density: -1000}
    position: [0.5, 0.5, 0.5]
)"),
            "scene.yaml:7: bodies[0].material.density = -1000: must be > 0");
}

TEST(Validation, NegativeRadius) {
  EXPECT_EQ(load_error(head + R"(bodies:
  - name: ball
    shape:
      type: sphere
      radius: -0.01
)"),
            "scene.yaml:8: bodies[0].shape.radius = -0.01: must be > 0");
}

TEST(Validation, ZeroBoxExtent) {
  EXPECT_EQ(load_error(head + R"(bodies:
  - name: brick
    shape: {type: box, half_extents: [0.1, 0, 0.1]}
)"),
            "scene.yaml:6: bodies[0].shape.half_extents = [0.1, 0, 0.1]: every entry must be > 0");
}

TEST(Validation, OtherMaterialAndShapeBounds) {
  EXPECT_EQ(load_error(head + "bodies:\n" + body(sphere + ", material: {density: 1, restitution: 1.5}")),
            "scene.yaml:5: bodies[0].material.restitution = 1.5: must be in [0, 1]");
  EXPECT_EQ(load_error(head + "bodies:\n" + body(sphere + ", material: {density: 1, friction: -0.1}")),
            "scene.yaml:5: bodies[0].material.friction = -0.1: must be >= 0");
  EXPECT_EQ(load_error(head + "bodies:\n  - {name: wall, shape: {type: plane, normal: [0, 0, 1]}}\n"),
            "scene.yaml:5: bodies[0].shape.type = plane: a plane must be a fixed body (add fixed: true)");
  EXPECT_EQ(load_error(head + "bodies:\n  - {name: wall, fixed: true, shape: {type: plane, normal: [0, 0, 0]}}\n"),
            "scene.yaml:5: bodies[0].shape.normal = [0, 0, 0]: must not be zero");
  EXPECT_EQ(load_error(head + "bodies:\n  - {name: rock, fixed: true, shape: {type: mesh, file: no/such.obj}}\n"),
            "scene.yaml:5: bodies[0].shape.file = no/such.obj: no such file: no/such.obj");
  EXPECT_EQ(load_error(head + "bodies:\n  - {name: thing, shape: {type: torus}}\n"),
            "scene.yaml:5: bodies[0].shape.type = torus: expected one of: "
            "sphere, ellipsoid, box, cylinder, capsule, plane, mesh");
}

TEST(Validation, SphereJustPokingOutOfTheDomain) {
  EXPECT_EQ(
      load_error(head + R"(bodies:
  - name: ball
    shape: {type: sphere, radius: 0.1}
    material: {density: 1000}
    position: [0.5, 0.5, 0.95]
)"),
      "scene.yaml:8: bodies[0].position = [0.5, 0.5, 0.95]: body 'ball' (extent [0.4, 0.4, 0.85] .. [0.6, 0.6, 1.05])"
      " is outside the domain [0, 0, 0] .. [1, 1, 1]");
}

TEST(Validation, SphereTouchingTheDomainIsInside) {
  EXPECT_EQ(load_error(head + "bodies:\n" + body(sphere + ", material: {density: 1}, position: [0.1, 0.5, 0.9]")), "");
}

TEST(Validation, RotatedBoxPokingOutOfTheDomain) {
  // Unrotated the box spans z in [0.19, 0.21]; turned 90 degrees about x its long y side
  // points along z and spans [-0.1, 0.5].
  const std::string box = head + R"(bodies:
  - name: plank
    shape: {type: box, half_extents: [0.01, 0.3, 0.01]}
    material: {density: 500}
    position: [0.5, 0.5, 0.2]
)";
  EXPECT_EQ(load_error(box), "");
  EXPECT_EQ(load_error(box + "    orientation: [0.70710678, 0.70710678, 0, 0]\n"),
            "scene.yaml:8: bodies[0].position = [0.5, 0.5, 0.2]: body 'plank' (extent [0.49, 0.49, -0.1] .. [0.51, "
            "0.51, 0.5])"
            " is outside the domain [0, 0, 0] .. [1, 1, 1]");
}

TEST(Validation, TiltedCylinderAndCapsuleReachFurther) {
  // Both stand upright with 0.05 to spare; tilted 90 degrees about y their axis lies along x.
  const auto rod = [](const std::string& type, const std::string& orientation) {
    return head + "bodies:\n  - {name: rod, shape: {type: " + type +
           ", radius: 0.05, height: 0.8}, material: {density: 1}," +
           " position: [0.1, 0.5, 0.5], orientation: " + orientation + "}\n";
  };
  const std::string upright = "[1, 0, 0, 0]", tilted = "[0.70710678, 0, 0.70710678, 0]";
  EXPECT_EQ(load_error(rod("cylinder", upright)), "");
  EXPECT_EQ(load_error(rod("capsule", upright)), "");
  EXPECT_EQ(
      load_error(rod("cylinder", tilted)),
      "scene.yaml:5: bodies[0].position = [0.1, 0.5, 0.5]: body 'rod' (extent [-0.3, 0.45, 0.45] .. [0.5, 0.55, 0.55])"
      " is outside the domain [0, 0, 0] .. [1, 1, 1]");
  EXPECT_EQ(load_error(rod("capsule", tilted)),
            "scene.yaml:5: bodies[0].position = [0.1, 0.5, 0.5]: body 'rod' (extent [-0.35, 0.45, 0.45] .. [0.55, "
            "0.55, 0.55])"
            " is outside the domain [0, 0, 0] .. [1, 1, 1]");
}

TEST(Validation, PlanePositionMustBeInside) {
  EXPECT_EQ(
      load_error(head + "bodies:\n  - {name: floor, fixed: true, shape: {type: plane, normal: [0, 0, 1]},"
                        " position: [0.5, 0.5, -0.1]}\n"),
      "scene.yaml:5: bodies[0].position = [0.5, 0.5, -0.1]: body 'floor' (extent [0.5, 0.5, -0.1] .. [0.5, 0.5, -0.1])"
      " lies wholly outside the domain [0, 0, 0] .. [1, 1, 1]");
}

// A fixed body may reach out of the domain (cut by a wall, or wrapped round a periodic face
// by the fluid), but not lie wholly outside it.
TEST(Validation, FixedBodyMayReachOutOfTheDomain) {
  const auto fixed_ball = [](const std::string& position) {
    return head + "bodies:\n  - {name: ball, fixed: true, shape: {type: sphere, radius: 0.1}, position: " + position +
           "}\n";
  };
  EXPECT_EQ(load_error(fixed_ball("[0.5, 0.5, 0.95]")), "");
  EXPECT_EQ(load_error(fixed_ball("[1.05, 0.5, 0.5]")), "");
  EXPECT_EQ(
      load_error(fixed_ball("[0.5, 0.5, 1.2]")),
      "scene.yaml:5: bodies[0].position = [0.5, 0.5, 1.2]: body 'ball' (extent [0.4, 0.4, 1.1] .. [0.6, 0.6, 1.3])"
      " lies wholly outside the domain [0, 0, 0] .. [1, 1, 1]");
}

TEST(Validation, DomainMustHaveVolume) {
  EXPECT_EQ(load_error("time: {end: 1}\ncoupling: {window: 0.01}\ndomain: {min: [0, 0, 0], max: [1, 0, 1]}\n"),
            "scene.yaml:3: domain.max = [1, 0, 1]: must be greater than domain.min in every component");
}

TEST(Validation, DtLongerThanWindow) {
  EXPECT_EQ(
      load_error(head + "participants:\n  spring: {command: [spring], dt: 0.02, provides: [forces]}\n"),
      "scene.yaml:5: participants.spring.dt = 0.02: window shorter than the participant's dt (coupling.window = 0.01)");
}

TEST(Validation, WindowNotAWholeNumberOfSteps) {
  EXPECT_EQ(
      load_error(head + "participants:\n  spring:\n    command: [spring]\n    dt: 0.003\n    provides: [forces]\n"),
      "scene.yaml:7: participants.spring.dt = 0.003: coupling.window is not a whole number of steps (coupling.window = "
      "0.01)");
}

TEST(Validation, EndNotAWholeNumberOfWindows) {
  EXPECT_EQ(load_error("time: {end: 1}\ncoupling: {window: 0.3}\n"),
            "scene.yaml:2: coupling.window = 0.3: time.end is not a whole number of windows (time.end = 1)");
  EXPECT_EQ(load_error("time: {end: 1}\ncoupling: {window: 2}\n"),
            "scene.yaml:2: coupling.window = 2: must be <= time.end (time.end = 1)");
}

TEST(Validation, CouplingBounds) {
  const auto coupling = [](const std::string& extra) {
    return load_error("time: {end: 1}\ncoupling: {window: 0.01, " + extra +
                      "}\ndomain: {min: [0, 0, 0], max: [1, 1, 1]}\n");
  };
  EXPECT_EQ(coupling("relaxation: 0"), "scene.yaml:2: coupling.relaxation = 0: must be in (0, 1]");
  EXPECT_EQ(coupling("tolerance: 1"), "scene.yaml:2: coupling.tolerance = 1: must be in (0, 1)");
  EXPECT_EQ(coupling("max_iterations: 0"), "scene.yaml:2: coupling.max_iterations = 0: must be >= 1");
  EXPECT_EQ(coupling("force_tolerance: -1"), "scene.yaml:2: coupling.force_tolerance = -1: must be >= 0");
  EXPECT_EQ(coupling("timeout: -5"), "scene.yaml:2: coupling.timeout = -5: must be > 0");
  EXPECT_EQ(coupling("transport: udp"), "scene.yaml:2: coupling.transport = udp: expected one of: ipc, tcp");
  EXPECT_EQ(coupling("heartbeat: 0.05"), "scene.yaml:2: coupling.heartbeat = 0.05: must be >= 0.1");
  EXPECT_EQ(coupling("interface: ib0"),
            "scene.yaml:2: coupling.interface = ib0: needs coupling.transport: tcp (an ipc socket is reached from "
            "this host only)");
  EXPECT_EQ(coupling("transport: tcp, interface: 0.0.0.0"),
            "scene.yaml:2: coupling.interface = 0.0.0.0: listening on every address gives participants no address "
            "to connect to; name one");
  EXPECT_EQ(
      coupling("transport: tcp, interface: 'tcp://ib0'"),
      "scene.yaml:2: coupling.interface = \"tcp://ib0\": expected a network interface (ib0, eth0) or an address of "
      "this host (10.1.2.3)");
  EXPECT_EQ(coupling("acceleration: anderson"),
            "scene.yaml:2: coupling.acceleration = anderson: expected one of: none, constant, aitken, iqn-ils");
}

TEST(Validation, BadSchemeName) {
  EXPECT_EQ(load_error("time: {end: 1}\ncoupling:\n  window: 0.01\n  scheme: implicit\n"),
            "scene.yaml:4: coupling.scheme = implicit: expected one of: "
            "serial-explicit, parallel-explicit, serial-implicit, parallel-implicit");
}

TEST(Validation, DuplicateKey) {
  EXPECT_EQ(load_error("time: {end: 1}\ncoupling: {window: 0.01}\ntime: {end: 2}\n"),
            "scene.yaml:3: time = {end: 2}: duplicate key (first at line 1)");
  EXPECT_EQ(load_error(head + "bodies:\n  - name: ball\n    name: bowl\n"),
            "scene.yaml:6: bodies[0].name = bowl: duplicate key (first at line 5)");
}

TEST(Validation, DuplicateBodyName) {
  EXPECT_EQ(load_error(head + "bodies:\n" + ball() + ball()),
            "scene.yaml:6: bodies[1].name = ball: duplicate body name (first at bodies[0])");
}

TEST(Validation, BadNames) {
  EXPECT_EQ(load_error(head + "bodies:\n  - {name: my ball}\n"),
            "scene.yaml:5: bodies[0].name = my ball: expected a name of 1 to 31 letters, digits, '_' and '-'");
  EXPECT_EQ(load_error(head + "participants:\n  my/spring: {}\n"),
            "scene.yaml:5: participants.my/spring = {}: expected a name of 1 to 31 letters, digits, '_' and '-'");
  const std::string too_long(32, 'a');  // it would not fit the protocol header
  EXPECT_EQ(
      load_error(head + "participants:\n  " + too_long + ": {}\n"),
      "scene.yaml:5: participants." + too_long + " = {}: expected a name of 1 to 31 letters, digits, '_' and '-'");
}

TEST(Validation, NonUnitQuaternion) {
  EXPECT_EQ(load_error(head + "bodies:\n" + ball(", orientation: [1, 0.1, 0, 0]")),
            "scene.yaml:5: bodies[0].orientation = [1, 0.1, 0, 0]: not a unit quaternion (norm 1.00499)");
}

TEST(Validation, MissingCommandForExternalParticipant) {
  EXPECT_EQ(load_error(head + "participants:\n  spring: {dt: 0.01, provides: [forces]}\n"),
            "scene.yaml:5: participants.spring.command: missing required key");
  EXPECT_EQ(load_error(head + "participants:\n  spring: {command: [], dt: 0.01, provides: [forces]}\n"),
            "scene.yaml:5: participants.spring.command = []: must name a program");
}

TEST(Validation, ProvidesOnABuiltIn) {
  EXPECT_EQ(load_error(head + "participants:\n  fluid:\n    dt: 0.01\n    provides: [forces]\n"),
            "scene.yaml:7: participants.fluid.provides = [forces]: "
            "'fluid' is a built-in participant whose roles follow from the effects; remove this key");
}

TEST(Validation, BadEffects) {
  EXPECT_EQ(load_error(head + "effects: [gravity, magnetism]\n"),
            "scene.yaml:4: effects[1] = magnetism: expected one of: "
            "gravity, buoyancy, hydrodynamics, contact, friction, rarefied_gas, tracers");
  EXPECT_EQ(load_error(head + "effects:\n  - gravity\n  - contact\n  - gravity\n"),
            "scene.yaml:7: effects[2] = gravity: listed twice");
}

TEST(Validation, EffectNeedingAMissingSection) {
  EXPECT_EQ(load_error(head + "bodies:\n" + ball() +
                       "effects: [gravity, hydrodynamics]\nparticipants:\n  rigidbody: {dt: 0.01}\n"),
            "scene.yaml:6: effects: effect 'hydrodynamics' needs participant 'fluid': add participants.fluid");
  EXPECT_EQ(load_error(head + "bodies:\n" + ball() + "effects: [contact]\n"),
            "scene.yaml:6: effects: effect 'contact' needs participant 'rigidbody': add participants.rigidbody");
}

TEST(Validation, NobodyProvidesPoses) {
  EXPECT_EQ(
      load_error(head + "participants:\n  monitor: {command: [monitor], dt: 0.01, provides: [], needs: [poses]}\n"),
      "scene.yaml:5: participants.monitor: needs poses but no started participant provides them");
}

TEST(Validation, TwoParticipantsProvidePoses) {
  EXPECT_EQ(
      load_error(head + "bodies:\n" + ball() + R"(effects: [gravity, hydrodynamics]
participants:
  rigidbody: {dt: 0.01}
  fluid: {dt: 0.01}
  mover: {command: [mover], dt: 0.01, provides: [poses]}
)"),
      "scene.yaml:10: participants.mover: provides poses, as does 'rigidbody'; only one participant may provide them");
}

TEST(Validation, YamlSyntaxErrorWithItsLine) {
  EXPECT_EQ(load_error("time: {end: 1}\ncoupling: {window: 0.01\ndomain: {}\n"),
            "scene.yaml:3: invalid YAML: end of map flow not found");
}

TEST(Validation, MissingFileOrADirectory) {
  EXPECT_EQ(thrown([] { cosim::scene::load_scene("/no/such/scene.yaml"); }), "/no/such/scene.yaml: no such scene file");
  EXPECT_EQ(thrown([] { cosim::scene::load_scene("/tmp"); }), "/tmp: not a file (a scene is a YAML file)");
}

}  // namespace
