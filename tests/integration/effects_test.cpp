// Simulate only what the scene calls for: one scene with a section for every program, run
// for real by `cosim run` with different effects. Each effect adds its program and nothing
// else, and fields cross the wire only to a consumer.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "tests/integration/cosim_process.hpp"
#include "tests/integration/h5_read.hpp"

namespace cosim::testing {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

// A ball in a 1 m box of rarefied argon or of a viscous liquid, whichever the effects call
// for: two windows of 1 ms.
std::string scene(const std::string& effects) {
  return "time: {end: 0.002}\n"
         "coupling: {window: 0.001, scheme: serial-explicit}\n"
         "output: {fields_every: 0}\n"
         "gravity: [0, 0, -9.81]\n"
         "domain: {min: [0, 0, 0], max: [1, 1, 1]}\n"
         "effects: " +
         effects +
         "\n"
         "bodies:\n"
         "  - {name: ball, shape: {type: sphere, radius: 0.1}, material: {density: 2000}, position: [0.5, 0.5, 0.5]}\n"
         "participants:\n"
         "  rigidbody: {dt: 1.0e-4, options: {fluid_density: 1000, walls: [z_min]}}\n"
         "  fluid:\n"
         "    dt: 1.0e-3\n"
         "    options: {density: 1000, viscosity: {model: newtonian, mu: 1.0}, grid: {cells: [8, 8, 8]}}\n"
         "  tracker:\n"
         "    dt: 1.0e-3\n"
         "    options:\n"
         "      mesh: {type: box, cells: [4, 4, 4]}\n"
         "      boundaries: {default: {kind: specular}}\n"
         "      obstacles: [{name: ball, body: ball, wall: {kind: diffuse, temperature: 300}}]\n"
         "      particles: {per_cell: 2, temperature: 300, mass: 6.63e-26, weight: 1.0e12, seed: 1}\n";
}

Finished run(const std::string& name, const std::string& effects) {
  const Finished f = run_scene_text(scratch_dir(name), scene(effects));
  EXPECT_EQ(f.exit_code, 0) << f.output;
  return f;
}

TEST(Effects, GravityAndContactStartOnlyTheRigidBodyProgram) {
  const Finished f = run("effects_rigid", "[gravity, contact]");
  EXPECT_THAT(f.output, HasSubstr("effects: gravity, contact"));
  EXPECT_THAT(f.output, HasSubstr("participants: rigidbody (provides poses, needs nothing)\n"));
  EXPECT_THAT(f.output, HasSubstr("started rigidbody"));
  EXPECT_THAT(f.output, Not(HasSubstr("started fluid")));
  EXPECT_THAT(f.output, Not(HasSubstr("started tracker")));
}

TEST(Effects, HydrodynamicsAddsTheFluidWhichSendsNoFieldsNobodyTakes) {
  const auto dir = scratch_dir("effects_fluid");
  const Finished f = run_scene_text(dir, scene("[gravity, contact, buoyancy, hydrodynamics]"));
  ASSERT_EQ(f.exit_code, 0) << f.output;
  EXPECT_THAT(
      f.output,
      HasSubstr("participants: rigidbody (provides poses, needs forces), fluid (provides forces, needs poses)\n"));
  EXPECT_THAT(f.output, HasSubstr("started fluid"));
  EXPECT_THAT(f.output, Not(HasSubstr("started tracker")));
  // Neither the run file (fields_every: 0) nor a participant takes the fluid's fields.
  for (const char* who : {"fluid", "rigidbody"}) {
    const Series bytes = read_series(dir / "scene.h5", std::string("/coupling/participants/") + who + "/field_bytes");
    ASSERT_EQ(bytes.rows, 3u);
    for (std::size_t k = 0; k < bytes.rows; ++k) EXPECT_EQ(bytes.at(k), 0.0) << who << ", window " << k;
  }
}

TEST(Effects, RarefiedGasAddsTheTracker) {
  const Finished f = run("effects_tracker", "[gravity, contact, rarefied_gas]");
  EXPECT_THAT(
      f.output,
      HasSubstr("participants: rigidbody (provides poses, needs forces), tracker (provides forces, needs poses)\n"));
  EXPECT_THAT(f.output, HasSubstr("started tracker"));
  EXPECT_THAT(f.output, Not(HasSubstr("started fluid")));
}

// Guards against: a scene with friction coefficients but no 'friction' effect running frictionless silently.
TEST(Effects, FrictionNoEffectUsesIsWarnedAboutByCheckAndRun) {
  const auto dir = scratch_dir("unused_friction");
  std::string yaml = scene("[gravity, contact]");
  yaml.replace(yaml.find("{density: 2000}"), 15, "{density: 2000, friction: 0.5}");
  const std::string warning = (dir / "scene.yaml").string() +
                              ":8: bodies[0].material.friction = 0.5: ignored for body 'ball': "
                              "the scene's effects do not include 'friction'";
  const Finished ran = run_scene_text(dir, yaml);
  EXPECT_EQ(ran.exit_code, 0) << ran.output;
  EXPECT_THAT(ran.output, HasSubstr("cosim: warning: " + warning));
  const Finished checked = run_cosim({"check", (dir / "scene.yaml").string()});
  EXPECT_EQ(checked.exit_code, 0) << checked.output;
  EXPECT_THAT(checked.output, HasSubstr("cosim: warning: " + warning));
}

// `cosim check` on the same scene: each built-in program reads its own section, so an
// option only that program knows is refused before a run, with file, line, key and value,
// instead of a scene called valid failing at the start of `cosim run`.
TEST(Check, EachProgramItStartsReadsItsOwnSection) {
  const auto dir = scratch_dir("check_sections");
  const std::string all = "[gravity, contact, hydrodynamics, rarefied_gas]";
  write_file(dir / "good.yaml", scene(all));
  const Finished good = run_cosim({"check", (dir / "good.yaml").string()});
  EXPECT_EQ(good.exit_code, 0) << good.output;
  EXPECT_THAT(good.output, HasSubstr("starts tracker"));

  struct Edit {
    std::string from, to, program, message;
  };
  const Edit edits[] = {
      {"walls: [z_min]", "walls: [z_mid]", "rigidbody",
       ":10: participants.rigidbody.options.walls[0] = z_mid: expected one of"},
      {"mu: 1.0", "mu: -1.0", "fluid", ":13: participants.fluid.options.viscosity.mu = -1.0: must be > 0"},
      {"type: box, cells: [4, 4, 4]", "type: gmsh, file: no-such.msh", "tracker",
       ":17: participants.tracker.options.mesh.file = no-such.msh"},
  };
  for (const Edit& e : edits) {
    std::string yaml = scene(all);
    yaml.replace(yaml.find(e.from), e.from.size(), e.to);
    const auto file = dir / (e.program + ".yaml");
    write_file(file, yaml);
    const Finished bad = run_cosim({"check", file.string()});
    EXPECT_EQ(bad.exit_code, 2) << bad.output;
    EXPECT_THAT(bad.output, HasSubstr("cosim-" + e.program + ": invalid scene: " + file.string() + e.message));
    EXPECT_THAT(bad.output,
                HasSubstr("cosim: invalid scene: " + file.string() + ": " + e.program + " refused its section"));
  }

  // A program that has not read its section within coupling.timeout is stopped and named:
  // no program starts, let alone reads a scene, in a millisecond.
  std::string slow = scene("[gravity, contact]");
  const std::string scheme = "scheme: serial-explicit}";
  slow.replace(slow.find(scheme), scheme.size(), "scheme: serial-explicit, timeout: 0.001}");
  write_file(dir / "slow.yaml", slow);
  const Finished stopped = run_cosim({"check", (dir / "slow.yaml").string()});
  EXPECT_EQ(stopped.exit_code, 2) << stopped.output;
  EXPECT_THAT(stopped.output, HasSubstr("cosim-rigidbody --check: killed by signal 15"));
  EXPECT_THAT(stopped.output, HasSubstr("given coupling.timeout = 0.001 s to read its section"));
}

}  // namespace
}  // namespace cosim::testing
