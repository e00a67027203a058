// Participants placed on other hosts: inside a Slurm allocation through srun (a fake srun
// on PATH records its arguments and runs the program here), elsewhere through mpirun.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <stdlib.h>

#include <filesystem>

#include "tests/integration/cosim_process.hpp"
#include "tests/integration/h5_read.hpp"
#include "tests/integration/oscillator_scene.hpp"

namespace cosim::testing {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

// Variables set for one test, restored after it.
class Environment {
 public:
  void set(const std::string& name, const std::string& value) {
    const char* old = getenv(name.c_str());
    saved_.emplace_back(name, old ? std::optional<std::string>(old) : std::nullopt);
    setenv(name.c_str(), value.c_str(), 1);
  }
  ~Environment() {
    for (auto it = saved_.rbegin(); it != saved_.rend(); ++it)
      it->second ? setenv(it->first.c_str(), it->second->c_str(), 1) : unsetenv(it->first.c_str());
  }

 private:
  std::vector<std::pair<std::string, std::optional<std::string>>> saved_;
};

OscillatorScene placed(std::vector<std::string> mass_keys, std::vector<std::string> spring_keys) {
  OscillatorScene s;
  s.end = 0.5;
  s.window = 0.01;
  s.dt_mass = s.dt_spring = 0.001;
  s.transport = "tcp";
  s.interface = "127.0.0.2";
  s.mass_keys = std::move(mass_keys);
  s.spring_keys = std::move(spring_keys);
  return s;
}

std::string program(const std::string& name) {
  return (fs::read_symlink("/proc/self/exe").parent_path() / name).string();
}

// Guards against: srun arguments that are not what Slurm documents for heterogeneous and
// per-node placement (srun(1): --het-group, --nodelist, --nodes, --ntasks, --exact).
TEST(Placement, InsideSlurmEachParticipantIsAnSrunStep) {
  const auto dir = scratch_dir("slurm");
  fs::create_directories(dir / "bin");
  fs::copy_file(COSIM_FAKE_SRUN, dir / "bin" / "srun");
  auto s = placed({"het_group: 1"}, {"hosts: [node7]"});
  const auto local = run_scene_text(dir, placed({}, {}).yaml(), "local");
  Finished r;
  {
    Environment env;
    env.set("SLURM_JOB_ID", "4242");
    env.set("PATH", (dir / "bin").string() + ":" + getenv("PATH"));
    env.set("FAKE_SRUN_DIR", dir.string());
    r = run_scene_text(dir, s.yaml(), "slurm");
  }
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(read_file(dir / "mass.args"), "--het-group=1\n--ntasks=1\n" + program("cosim-test-oscillator-mass") + "\n");
  EXPECT_EQ(read_file(dir / "spring.args"),
            "--nodelist=node7\n--nodes=1\n--ntasks=1\n--exact\n" + program("cosim-test-oscillator-spring") + "\n");
  ASSERT_EQ(local.exit_code, 0) << local.output;
  EXPECT_EQ(read_series(dir / "slurm.h5", "/bodies/m1/position").values,
            read_series(dir / "local.h5", "/bodies/m1/position").values);
}

TEST(Placement, HostsAndHostfileGoToMpirunWithTheCouplersVariables) {
  const auto dir = scratch_dir("mpirun_hosts");
  write_file(dir / "nodes.txt", "node1 slots=4\nnode2 slots=4\n");
  write_file(dir / "scene.yaml", placed({"hostfile: nodes.txt", "ranks: 4"}, {"hosts: [node1, node2]"}).yaml());
  const auto r = run_cosim({"check", (dir / "scene.yaml").string()});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string forwarded =
      " -x COSIM_ENDPOINT -x COSIM_PARTICIPANT -x COSIM_HEARTBEAT -x COSIM_CURVE_SERVER_KEY -x COSIM_CURVE_PUBLIC_KEY"
      " -x COSIM_CURVE_SECRET_KEY ";
  EXPECT_THAT(r.output,
              ::testing::ContainsRegex("starts mass .*mpirun -n 4 --hostfile " + (dir / "nodes.txt").string() +
                                       forwarded + program("cosim-test-oscillator-mass")));
  EXPECT_THAT(r.output, ::testing::ContainsRegex("starts spring .*mpirun -n 1 --host node1,node2" + forwarded +
                                                 program("cosim-test-oscillator-spring")));
}

TEST(Placement, SchedulerPlacementOutsideSlurmIsASceneError) {
  const auto dir = scratch_dir("no_slurm");
  unsetenv("SLURM_JOB_ID");
  write_file(dir / "scene.yaml", placed({"hosts: scheduler"}, {}).yaml());
  const auto r = run_cosim({"check", (dir / "scene.yaml").string()});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("participants.mass.hosts = scheduler: needs a Slurm allocation"));
}

TEST(Placement, OtherHostsNeedANetworkInterface) {
  const auto dir = scratch_dir("no_interface");
  auto s = placed({}, {"hosts: [node1]"});
  s.interface.clear();
  write_file(dir / "scene.yaml", s.yaml());
  const auto r = run_cosim({"check", (dir / "scene.yaml").string()});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("participants.spring.hosts = [node1]: ranks on other hosts reach the coupler only "
                                  "over a network: set coupling.transport: tcp and coupling.interface"));
}

}  // namespace
}  // namespace cosim::testing
