#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "tests/integration/cosim_process.hpp"
#include "rigidbody/program/scene_world.hpp"
#include "coupler/scene/error.hpp"

namespace cosim::rigidbody::program {
namespace {

using std::numbers::pi;

std::string scene_text(const std::string& effects, const std::string& bodies, const std::string& options = "{}") {
  return "time: {end: 0.1}\ncoupling: {window: 0.01, scheme: serial-explicit}\n"
         "domain: {min: [-5, -5, -5], max: [5, 5, 5]}\neffects: " +
         effects + "\nbodies:\n" + bodies + "participants:\n  rigidbody: {dt: 1.0e-3, options: " + options + "}\n";
}

const std::string ball =
    "  - {name: ball, shape: {type: sphere, radius: 0.1}, material: {density: 2500}, position: [0, 0, 1]}\n";

double mass(const world::World& w, std::uint32_t i) { return 1.0 / w.inertias()[i].inverse_mass; }

struct Refusal {
  std::string key, message;
};

// What reading the options of `text` with `read` refuses (a failure if it accepts them).
template <typename Read>
Refusal refusal(const std::string& text, Read read) {
  try {
    read(scene::load_scene_from_string(text));
  } catch (const scene::SceneError& e) {
    return {e.key, e.what()};
  }
  ADD_FAILURE() << "accepted:\n" << text;
  return {};
}

TEST(SceneWorld, EveryShapeHasTheMassOfItsVolume) {
  const auto dir = testing::scratch_dir("shapes");
  // A unit cube as an ASCII STL, its corner at the origin: the centre of mass is at 0.5.
  std::string stl = "solid cube\n";
  const auto facet = [&](std::array<double, 9> v) {
    stl += "facet normal 0 0 0\nouter loop\n";
    for (int k = 0; k < 3; ++k)
      stl += "vertex " + std::to_string(v[3 * k]) + " " + std::to_string(v[3 * k + 1]) + " " +
             std::to_string(v[3 * k + 2]) + "\n";
    stl += "endloop\nendfacet\n";
  };
  facet({0, 0, 0, 0, 1, 0, 1, 1, 0});
  facet({0, 0, 0, 1, 1, 0, 1, 0, 0});
  facet({0, 0, 1, 1, 0, 1, 1, 1, 1});
  facet({0, 0, 1, 1, 1, 1, 0, 1, 1});
  facet({0, 0, 0, 1, 0, 0, 1, 0, 1});
  facet({0, 0, 0, 1, 0, 1, 0, 0, 1});
  facet({0, 1, 0, 0, 1, 1, 1, 1, 1});
  facet({0, 1, 0, 1, 1, 1, 1, 1, 0});
  facet({0, 0, 0, 0, 0, 1, 0, 1, 1});
  facet({0, 0, 0, 0, 1, 1, 0, 1, 0});
  facet({1, 0, 0, 1, 1, 0, 1, 1, 1});
  facet({1, 0, 0, 1, 1, 1, 1, 0, 1});
  testing::write_file(dir / "cube.stl", stl + "endsolid cube\n");
  const std::string body = "    material: {density: 1000}\n    position: [1, 2, 3]\n";
  const auto scene = scene::load_scene_from_string(
      scene_text(
          "[gravity]",
          "  - {name: s, shape: {type: sphere, radius: 0.1}, material: {density: 1000}, position: [0, 0, 0]}\n"
          "  - {name: e, shape: {type: ellipsoid, radii: [0.1, 0.2, 0.3]}, material: {density: 1000}, position: [0, 0, 0]}\n"
          "  - {name: b, shape: {type: box, half_extents: [0.1, 0.2, 0.3]}, material: {density: 1000}, position: [0, 0, 0]}\n"
          "  - {name: c, shape: {type: cylinder, radius: 0.1, height: 0.4}, material: {density: 1000}, position: [0, 0, 0]}\n"
          "  - {name: k, shape: {type: capsule, radius: 0.1, height: 0.4}, material: {density: 1000}, position: [0, 0, 0]}\n"
          "  - {name: p, shape: {type: plane, normal: [0, 0, 1]}, fixed: true, position: [0, 0, -1]}\n"
          "  - name: m\n    shape: {type: mesh, file: cube.stl}\n" +
              body),
      dir / "scene.yaml");
  const auto world = make_world(scene);
  const auto& w = *world;
  const double r = 0.1;
  EXPECT_NEAR(mass(w, 0), 1000 * 4.0 / 3.0 * pi * r * r * r, 1e-9);
  EXPECT_NEAR(mass(w, 1), 1000 * 4.0 / 3.0 * pi * 0.1 * 0.2 * 0.3, 1e-9);
  EXPECT_NEAR(mass(w, 2), 1000 * 0.2 * 0.4 * 0.6, 1e-9);
  EXPECT_NEAR(mass(w, 3), 1000 * pi * r * r * 0.4, 1e-9);
  EXPECT_NEAR(mass(w, 4), 1000 * (pi * r * r * 0.4 + 4.0 / 3.0 * pi * r * r * r), 1e-9);
  EXPECT_TRUE(w.inertias()[5].is_fixed());
  EXPECT_EQ(geometry::kind(w.shape(5)), geometry::ShapeKind::HalfSpace);
  EXPECT_DOUBLE_EQ(w.states()[5].position.z(), -1.0);  // the plane passes through the body position
  EXPECT_NEAR(mass(w, 6), 1000.0, 1e-6);
  // The file put the cube's centre at (0.5, 0.5, 0.5) of its frame; the body sits there.
  EXPECT_NEAR((w.states()[6].position - Eigen::Vector3d(1.5, 2.5, 3.5)).norm(), 0.0, 1e-6);
}

const auto read_settings = [](const scene::Scene& scene) { settings_of(scene); };

TEST(SceneWorld, UnknownOptionIsNamed) {
  EXPECT_EQ(refusal(scene_text("[gravity]", ball, "{iteration: 5}"), read_settings).key,
            "participants.rigidbody.options.iteration");
}

TEST(SceneWorld, BadSolverIsNamed) {
  EXPECT_EQ(refusal(scene_text("[gravity]", ball, "{solver: newton}"), read_settings).key,
            "participants.rigidbody.options.solver");
}

TEST(SceneWorld, BuoyancyNeedsFluidDensity) {
  EXPECT_EQ(refusal(scene_text("[gravity, buoyancy]", ball), read_settings).key,
            "participants.rigidbody.options.fluid_density");
  const auto with = scene::load_scene_from_string(scene_text("[gravity, buoyancy]", ball, "{fluid_density: 1000}"));
  EXPECT_EQ(settings_of(with).body_forces.fluid_density, 1000.0);
}

TEST(SceneWorld, VirtualMassNeedsFluidDensity) {
  const Refusal r =
      refusal(scene_text("[gravity]", ball, "{virtual_mass: 1}"), [](const scene::Scene& s) { program_options(s); });
  EXPECT_EQ(r.key, "participants.rigidbody.options.virtual_mass");
  EXPECT_NE(r.message.find("fluid_density"), std::string::npos) << r.message;
  const auto with =
      scene::load_scene_from_string(scene_text("[gravity]", ball, "{virtual_mass: 0.5, fluid_density: 1000}"));
  EXPECT_EQ(program_options(with).virtual_mass, 0.5);
}

TEST(SceneWorld, OptionsReachTheSettings) {
  const auto scene = scene::load_scene_from_string(
      scene_text("[gravity]", ball,
                 "{solver: pgs, iterations: 7, tolerance: 1.0e-4, contact_margin: 0.01, restitution: sequential}"));
  const auto s = settings_of(scene);
  EXPECT_EQ(s.solver, world::SolverKind::pgs);
  EXPECT_EQ(s.iterations, 7);
  EXPECT_EQ(s.tolerance, 1e-4);
  EXPECT_EQ(s.contact_margin, 0.01);
  EXPECT_EQ(s.restitution, solver::Restitution::sequential);
  EXPECT_EQ(s.dt, 1e-3);
}

TEST(SceneWorld, EffectsSwitchGravityContactAndFriction) {
  const std::string rough =
      "  - {name: ball, shape: {type: sphere, radius: 0.1}, material: {density: 2500, friction: 0.4}, position: [0, 0, 1]}\n";
  const auto bare = settings_of(scene::load_scene_from_string(scene_text("[contact]", ball)));
  EXPECT_FALSE(bare.body_forces.gravity);
  EXPECT_TRUE(bare.contact);
  const auto falling = settings_of(scene::load_scene_from_string(scene_text("[gravity]", ball)));
  EXPECT_TRUE(falling.body_forces.gravity);
  EXPECT_FALSE(falling.contact);
  const auto frictionless = scene::load_scene_from_string(scene_text("[gravity, contact]", rough));
  EXPECT_EQ(body_of(frictionless.bodies[0], false).material.friction, 0.0);
  EXPECT_EQ(body_of(frictionless.bodies[0], true).material.friction, 0.4);
}

TEST(SceneWorld, DemOptionsReachTheSettings) {
  const auto scene = scene::load_scene_from_string(
      scene_text("[gravity]", ball, "{solver: dem, dem_law: hertz, normal_stiffness: 2.0e6}"));
  const auto s = settings_of(scene);
  EXPECT_EQ(s.solver, world::SolverKind::dem);
  EXPECT_EQ(s.dem.law, solver::NormalLaw::hertz);
  EXPECT_EQ(s.dem.normal_stiffness, 2e6);
  EXPECT_EQ(settings_of(scene::load_scene_from_string(scene_text("[gravity]", ball))).dem.law,
            solver::NormalLaw::linear);
}

// The error names file, line, key and value, as every scene error does.
scene::SceneError error_of(const std::string& options, const std::string& bodies = ball) {
  const auto scene = scene::load_scene_from_string(scene_text("[gravity]", bodies, options), "scene.yaml");
  try {
    make_world(scene);
  } catch (const scene::SceneError& e) {
    return e;
  }
  throw std::logic_error("no error for options " + options);
}

TEST(SceneWorld, BadDemOptionsAreNamed) {
  const auto law = error_of("{dem_law: cubic}");
  EXPECT_EQ(law.key, "participants.rigidbody.options.dem_law");
  EXPECT_EQ(law.value, "cubic");
  EXPECT_EQ(law.line, 8);  // the options line
  EXPECT_NE(std::string(law.what()).find("scene.yaml:8: participants.rigidbody.options.dem_law = cubic: "),
            std::string::npos)
      << law.what();
  const auto k = error_of("{normal_stiffness: -1}");
  EXPECT_EQ(k.key, "participants.rigidbody.options.normal_stiffness");
  EXPECT_EQ(k.value, "-1");
}

TEST(SceneWorld, SoftStepOptionsReachTheSettings) {
  const auto s = settings_of(scene::load_scene_from_string(
      scene_text("[gravity, contact]", ball, "{iterations: 3, substeps: 4, relax_iterations: 1, contact_hertz: 900}")));
  EXPECT_EQ(s.solver, world::SolverKind::soft);
  EXPECT_EQ(s.soft_options().iterations, 3);
  EXPECT_EQ(s.soft.substeps, 4);
  EXPECT_EQ(s.soft.relax_iterations, 1);
  EXPECT_EQ(s.soft.hertz, 900.0);
  const auto none = error_of("{substeps: 0}");
  EXPECT_EQ(none.key, "participants.rigidbody.options.substeps");
  EXPECT_EQ(none.value, "0");
  EXPECT_EQ(error_of("{contact_hertz: -5}").key, "participants.rigidbody.options.contact_hertz");
  EXPECT_EQ(error_of("{relax_iterations: 1.5}").key, "participants.rigidbody.options.relax_iterations");
  // Another solver has no use for them: a warning, and they stay out of its run.
  EXPECT_EQ(settings_of(scene::load_scene_from_string(
                            scene_text("[gravity, contact]", ball, "{solver: sequential-impulses, substeps: 4}")))
                .solver,
            world::SolverKind::sequential_impulses);
}

TEST(SceneWorld, LubricationReachesTheSettings) {
  const auto s = settings_of(scene::load_scene_from_string(
      scene_text("[gravity, contact]", ball, "{lubrication: {viscosity: 0.058, range: 2.5e-3}}")));
  EXPECT_EQ(s.lubrication.viscosity, 0.058);
  EXPECT_EQ(s.lubrication.range, 2.5e-3);
  EXPECT_DOUBLE_EQ(s.lubrication.roughness, 2.5e-6);  // a thousandth of the range unless given
  EXPECT_FALSE(settings_of(scene::load_scene_from_string(scene_text("[gravity, contact]", ball))).lubrication.active());
  // Without contact there are no pairs to act on: a warning, and no film.
  EXPECT_FALSE(settings_of(scene::load_scene_from_string(
                               scene_text("[gravity]", ball, "{lubrication: {viscosity: 0.058, range: 2.5e-3}}")))
                   .lubrication.active());
}

// `lubrication: auto` takes the film from the scene's fluid: its Newtonian viscosity, and
// the gap its method resolves: 0.4 of its widest cell with the immersed boundary
// (fluid_accuracy --wall-approach), the whole cell with the staircase.
TEST(SceneWorld, AutoLubricationTakesTheFluidsViscosityAndCell) {
  const auto with_bodies = [](const std::string& bodies) {
    return "  fluid: {dt: 1.0e-3, options: {density: 1000, viscosity: {model: newtonian, mu: 0.058}, grid: {cells: "
           "[20, 40, 1]}" +
           bodies + "}}\n";
  };
  const auto s = settings_of(scene::load_scene_from_string(
      scene_text("[gravity, contact, hydrodynamics]", ball, "{lubrication: auto}") + with_bodies("")));
  EXPECT_EQ(s.lubrication.viscosity, 0.058);
  const double cell = 10.0 / 20;  // the domain is 10 m wide; the one-cell axis does not count
  EXPECT_DOUBLE_EQ(s.lubrication.range, 0.4 * cell);
  EXPECT_DOUBLE_EQ(s.lubrication.roughness, 1e-3 * s.lubrication.range);
  const auto staircase = settings_of(
      scene::load_scene_from_string(scene_text("[gravity, contact, hydrodynamics]", ball, "{lubrication: auto}") +
                                    with_bodies(", bodies: {method: staircase}")));
  EXPECT_DOUBLE_EQ(staircase.lubrication.range, cell);
  EXPECT_EQ(error_of("{lubrication: automatic}").key, "participants.rigidbody.options.lubrication");
  const std::string carreau =
      "  fluid: {dt: 1.0e-3, options: {density: 1000, viscosity: {model: carreau, mu_zero: 1, mu_infinity: 0.1, "
      "time_constant: 1, index: 0.5}, grid: {cells: [20, 40, 1]}}}\n";
  try {
    settings_of(scene::load_scene_from_string(
        scene_text("[gravity, contact, hydrodynamics]", ball, "{lubrication: auto}") + carreau));
    FAIL() << "auto lubrication with a Carreau fluid";
  } catch (const scene::SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("needs a Newtonian fluid"), std::string::npos) << e.what();
  }
}

TEST(SceneWorld, BadLubricationIsNamed) {
  const auto rough = error_of("{lubrication: {viscosity: 0.058, range: 1.0e-3, roughness: 2.0e-3}}");
  EXPECT_EQ(rough.key, "participants.rigidbody.options.lubrication.roughness");
  EXPECT_EQ(rough.value, "2.0e-3");
  EXPECT_EQ(error_of("{lubrication: {range: 1.0e-3}}").key, "participants.rigidbody.options.lubrication.viscosity");
  EXPECT_EQ(error_of("{lubrication: {viscosity: 0.058, range: 1.0e-3, gap: 1}}").key,
            "participants.rigidbody.options.lubrication.gap");
}

const std::string gem_and_ball = ball + "  - {name: gem, shape: {type: mesh, file: " COSIM_CONFIGS_DIR
                                        "/meshes/icosahedron.obj}, material: {density: 1000}, position: [1, 0, 1]}\n";

TEST(SceneWorld, ConvexHullsTurnMeshBodiesIntoHulls) {
  const auto mesh = make_world(scene::load_scene_from_string(scene_text("[gravity]", gem_and_ball)));
  const auto hull =
      make_world(scene::load_scene_from_string(scene_text("[gravity]", gem_and_ball, "{convex_hulls: [gem]}")));
  EXPECT_EQ(geometry::kind(mesh->shape(1)), geometry::ShapeKind::TriangleMesh);
  EXPECT_EQ(geometry::kind(hull->shape(1)), geometry::ShapeKind::ConvexHull);
  // A convex mesh and its hull are the same solid, at the same place.
  EXPECT_NEAR(mass(*hull, 1), mass(*mesh, 1), 1e-9 * mass(*mesh, 1));
  EXPECT_NEAR((hull->states()[1].position - mesh->states()[1].position).norm(), 0.0, 1e-12);
}

TEST(SceneWorld, ConvexHullsOfNonMeshesAreNamed) {
  const auto e = error_of("{convex_hulls: [gem, ball]}", gem_and_ball);
  EXPECT_EQ(e.key, "participants.rigidbody.options.convex_hulls[1]");
  EXPECT_EQ(e.value, "ball");
  EXPECT_NE(std::string(e.what()).find("gem"), std::string::npos) << e.what();  // the meshes it could name
}

}  // namespace
}  // namespace cosim::rigidbody::program
