// Implicit coupling repeats windows: a restore must give back exactly the run it repeats,
// warm-started contact impulses included.
#include <gtest/gtest.h>

#include "coupler/protocol/message.hpp"
#include "rigidbody/program/adapter.hpp"

namespace cosim::rigidbody::program {
namespace {

// Two boxes resting on a plane and a third falling onto them: contacts that persist over
// windows (warm starts matter) and one that is new.
scene::Scene boxes() {
  return scene::load_scene_from_string(
      "time: {end: 1.0}\ncoupling: {window: 0.01, scheme: serial-implicit}\n"
      "domain: {min: [-1, -1, -0.1], max: [1, 1, 2]}\neffects: [gravity, contact, friction]\n"
      "bodies:\n"
      "  - {name: floor, shape: {type: plane, normal: [0, 0, 1]}, fixed: true, position: [0, 0, 0], material: {friction: 0.5}}\n"
      "  - {name: a, shape: {type: box, half_extents: [0.1, 0.1, 0.1]}, material: {density: 1000, friction: 0.5}, position: [0, 0, 0.1]}\n"
      "  - {name: b, shape: {type: box, half_extents: [0.1, 0.1, 0.1]}, material: {density: 1000, friction: 0.5}, position: [0.02, 0, 0.3]}\n"
      "  - {name: c, shape: {type: sphere, radius: 0.05}, material: {density: 1000, friction: 0.5}, position: [0.05, 0.03, 0.5]}\n"
      "participants:\n  rigidbody: {dt: 1.0e-3, options: {solver: sequential-impulses, iterations: 10}}\n");
}

// The poses after the last window, as their wire values.
std::vector<double> run_windows(RigidSolver& solver, std::uint64_t from, std::uint64_t to) {
  std::vector<participant::PoseRow> poses;
  for (std::uint64_t k = from; k < to; ++k) poses = solver.advance({k, 1, k * 0.01, (k + 1) * 0.01}, {}).poses;
  return participant::values_of(poses);
}

// Guards against: an implicit window repeated after a restore differing in the last bit (lost contact
// memory).
TEST(Rollback, RepeatsTheWindowsBitForBit) {
  RigidSolver solver;
  solver.initialise(boxes(), "rigidbody", {}, {});
  run_windows(solver, 0, 10);
  const std::vector<double> saved = solver.state();
  const std::vector<double> first = run_windows(solver, 10, 30);
  const std::vector<double> first_state = solver.state();

  solver.restore(saved);
  EXPECT_EQ(solver.state(), saved);
  EXPECT_EQ(run_windows(solver, 10, 30), first);
  EXPECT_EQ(solver.state(), first_state);

  // Without the contact memory (a cold start after the restore) the run differs: the
  // memory is what makes the repeat exact, and this test would see it go missing.
  std::vector<double> cold(saved.begin(), saved.begin() + 1 + protocol::kPoseWidth * 4);
  cold.insert(cold.end(), {0.0, 0.0});
  solver.restore(cold);
  EXPECT_NE(run_windows(solver, 10, 30), first);
}

TEST(Rollback, RejectsAMalformedState) {
  RigidSolver solver;
  solver.initialise(boxes(), "rigidbody", {}, {});
  run_windows(solver, 0, 5);
  std::vector<double> state = solver.state();
  EXPECT_THROW(solver.restore({0.0, 1.0}), std::runtime_error);
  state.push_back(1.0);  // one value too many for the memory's own counts
  try {
    solver.restore(state);
    FAIL() << "restored a state with a trailing value";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("saved contact memory"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace cosim::rigidbody::program
