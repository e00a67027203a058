#include "coupler/scene/plan.hpp"

#include <gtest/gtest.h>

#include "tests/scene/errors.hpp"

namespace cosim::scene {
namespace {

constexpr DataSet poses = static_cast<DataSet>(Data::Poses);
constexpr DataSet forces = static_cast<DataSet>(Data::Forces);
constexpr DataSet fields = static_cast<DataSet>(Data::Fields);

const std::string all_builtins = R"(participants:
  rigidbody: {dt: 0.01}
  fluid: {dt: 0.01}
  tracker: {dt: 0.01}
)";

// A scene with every built-in section, one body (fixed or not) and the given effects.
Plan plan_for(const std::string& effects, bool fixed) {
  const std::string body =
      std::string("bodies: [{name: ball, fixed: ") + (fixed ? "true" : "false") +
      ", shape: {type: sphere, radius: 0.1}, material: {density: 1000}, position: [0.5, 0.5, 0.5]}]\n";
  return plan_participants(load_scene_from_string(head + body + "effects: " + effects + "\n" + all_builtins));
}

std::vector<std::string> names(const Plan& plan) {
  std::vector<std::string> out;
  for (const Participant& p : plan.start) out.push_back(p.name);
  return out;
}

using Names = std::vector<std::string>;

TEST(Plan, GravityMovesTheBodiesAlone) {
  const Plan plan = plan_for("[gravity]", false);
  EXPECT_EQ(names(plan), Names{"rigidbody"});
  EXPECT_EQ(plan.start[0].provides, poses);
  EXPECT_EQ(plan.start[0].needs, 0u);
  EXPECT_EQ(plan.skipped, (Names{"fluid: no declared effect needs it", "tracker: no declared effect needs it"}));
}

TEST(Plan, GravityWithOnlyFixedBodiesNeedsNobody) {
  const Plan plan = plan_for("[gravity, contact]", true);
  EXPECT_TRUE(plan.start.empty());
  EXPECT_EQ(plan.skipped.front(), "rigidbody: no body is free to move");
}

TEST(Plan, HydrodynamicsCouplesFluidAndBodies) {
  const Plan plan = plan_for("[gravity, hydrodynamics]", false);
  EXPECT_EQ(names(plan), (Names{"rigidbody", "fluid"}));
  EXPECT_EQ(plan.start[0].provides, poses);
  EXPECT_EQ(plan.start[0].needs, forces);
  EXPECT_EQ(plan.start[1].provides, forces | fields);  // the run file takes its fields
  EXPECT_EQ(plan.start[1].needs, poses);
}

TEST(Plan, HydrodynamicsAroundFixedBodiesIsFluidOnly) {
  const Plan plan = plan_for("[hydrodynamics]", true);
  EXPECT_EQ(names(plan), Names{"fluid"});
  EXPECT_EQ(plan.start[0].provides, forces | fields);
  EXPECT_EQ(plan.start[0].needs, 0u);
}

TEST(Plan, WithoutFieldOutputTheFluidSendsOnlyForces) {
  const std::string scene = head + "output: {fields_every: 0}\neffects: [hydrodynamics]\n" + all_builtins;
  const Plan plan = plan_participants(load_scene_from_string(scene));
  EXPECT_EQ(plan.start.at(0).provides, forces);
}

TEST(Plan, TracersRideTheFluid) {
  const Plan plan = plan_for("[tracers]", true);
  EXPECT_EQ(names(plan), (Names{"fluid", "tracker"}));
  EXPECT_EQ(plan.start[0].provides, fields);
  EXPECT_EQ(plan.start[1].provides, fields);  // its samples, for the run file
  EXPECT_EQ(plan.start[1].needs, fields);
}

TEST(Plan, TracersInARarefiedGasNeedNoFluid) {
  const Plan plan = plan_for("[rarefied_gas, tracers]", false);
  EXPECT_EQ(names(plan), (Names{"rigidbody", "tracker"}));
  EXPECT_EQ(plan.start[1].provides, forces | fields);
  EXPECT_EQ(plan.start[1].needs, poses);
  EXPECT_EQ(plan.start[0].needs, forces);
  EXPECT_EQ(plan.skipped, Names{"fluid: no declared effect needs it"});
}

TEST(Plan, TracersAroundMovingBodiesNeedSomethingToMoveThem) {
  EXPECT_EQ(thrown([] { plan_for("[tracers]", false); }),
            "<string>:8: participants.fluid: needs poses but no started participant provides them");
}

TEST(Plan, NoEffectsStartsOnlyExternals) {
  const Scene s = load_scene_from_string(head + R"(participants:
  fluid: {dt: 0.01}
  logger: {command: [logger, -v], dt: 0.01, provides: [], needs: [fields]}
  heater: {command: [heater], ranks: 2, dt: 0.005, provides: [fields]}
)");
  const Plan plan = plan_participants(s);
  EXPECT_EQ(names(plan), (Names{"logger", "heater"}));
  EXPECT_EQ(plan.start[0].needs, fields);
  EXPECT_EQ(plan.start[1].ranks, 2);
  EXPECT_EQ(plan.skipped, Names{"fluid: no declared effect needs it"});
}

TEST(Plan, ExternalForcesReachTheRigidBodies) {
  const Scene s = load_scene_from_string(
      head +
      R"(bodies: [{name: b, shape: {type: sphere, radius: 0.1}, material: {density: 1}, position: [0.5, 0.5, 0.5]}]
effects: [gravity]
participants:
  spring: {command: [spring], dt: 0.01, provides: [forces], needs: [poses]}
  rigidbody: {dt: 0.001}
)");
  const Plan plan = plan_participants(s);
  EXPECT_EQ(names(plan), (Names{"spring", "rigidbody"}));
  EXPECT_EQ(plan.start[1].needs, forces);
}

TEST(Plan, MissingSectionIsCaughtOnAHandBuiltSceneToo) {
  Scene s = load_scene_from_string(head, "scene.yaml");
  s.effects = {Effect::RarefiedGas};
  s.effects_line = 9;
  EXPECT_EQ(thrown([&] { plan_participants(s); }),
            "scene.yaml:9: effects: effect 'rarefied_gas' needs participant 'tracker': add participants.tracker");
}

}  // namespace
}  // namespace cosim::scene
