// Runs inside a real Slurm allocation (label slurm): a one-machine cluster of Debian's
// slurm-wlm (slurm_cluster.hpp), the coupled oscillator submitted with sbatch as docs/scenes.md's
// script does, its spring started by srun as a step of the job, as a component of a
// heterogeneous job, on the nodes of a hostfile; a job cancelled mid-run then resumed
// bit-identically. Skipped, with the reason, where the daemons cannot run.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <thread>

#include "tests/integration/cosim_process.hpp"
#include "tests/integration/h5_read.hpp"
#include "tests/integration/oscillator_scene.hpp"
#include "tests/integration/slurm_cluster.hpp"

namespace cosim::testing {
namespace {

using namespace std::chrono_literals;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

const std::vector<std::string> kSeries{"/bodies/m1/time", "/bodies/m1/position", "/bodies/m1/force",
                                       "/coupling/iterations"};

std::string output_of(const std::string& command) {
  std::string out;
  if (std::FILE* p = popen((command + " 2>&1").c_str(), "r")) {
    char buffer[256];
    while (std::fgets(buffer, sizeof buffer, p) != nullptr) out += buffer;
    pclose(p);
  }
  return out;
}

class Slurm : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    cluster_ = new SlurmCluster();
    if (cluster_->running()) setenv("SLURM_CONF", cluster_->conf().c_str(), 1);
  }
  static void TearDownTestSuite() {
    delete cluster_;
    cluster_ = nullptr;
  }

  void SetUp() override {
    if (!cluster_->running()) GTEST_SKIP() << cluster_->why();
    dir_ = scratch_dir(::testing::UnitTest::GetInstance()->current_test_info()->name());
    ASSERT_EQ(run_scene_text(dir_, OscillatorScene{}.yaml(), "local").exit_code, 0);
  }

  // The oscillator with the spring placed by `placement` (a scene key of its section),
  // the coupler listening on this host's loopback for it.
  static OscillatorScene placed(const std::string& placement) {
    OscillatorScene s;
    s.transport = "tcp";
    s.interface = "127.0.0.1";
    s.checkpoint_every = 7;
    s.spring_keys = {placement};
    return s;
  }

  // A batch script that runs `cosim <arguments>` in an allocation of `header` (#SBATCH
  // lines), its output in DIR/<stem>.out.
  fs::path script(const std::string& stem, const std::string& header, const std::string& arguments) const {
    const auto cosim = fs::read_symlink("/proc/self/exe").parent_path() / "cosim";
    const auto path = dir_ / (stem + ".sh");
    write_file(path, "#!/bin/bash\n" + header + cosim.string() + " " + arguments + "\n");
    return path;
  }

  // sbatch --wait: the job's exit status (124 if it did not end within two minutes).
  int submit_and_wait(const fs::path& job, const std::string& stem) const {
    const int status = std::system(("timeout 120 sbatch --wait --quiet --output=" + (dir_ / (stem + ".out")).string() +
                                    " " + job.string() + " >/dev/null 2>&1")
                                       .c_str());
    return WEXITSTATUS(status);
  }

  std::string job_output(const std::string& stem) const { return read_file(dir_ / (stem + ".out")); }

  void expect_same_as_local(const std::string& stem) const {
    for (const auto& series : kSeries)
      EXPECT_EQ(read_series(dir_ / "local.h5", series).values, read_series(dir_ / (stem + ".h5"), series).values)
          << series;
  }

  // The oscillator placed by `placement`, run by a job of `header`: it finishes, its
  // participant starts with `launch` in its command line, and its series are the local run's.
  void run_placed(const std::string& stem, const std::string& placement, const std::string& header,
                  const std::string& launch) const {
    write_file(dir_ / (stem + ".yaml"), placed(placement).yaml());
    const auto job = script(
        stem, header, "run " + (dir_ / (stem + ".yaml")).string() + " -o " + (dir_ / (stem + ".h5")).string() + " -q");
    ASSERT_EQ(submit_and_wait(job, stem), 0) << job_output(stem);
    EXPECT_THAT(job_output(stem), HasSubstr(launch));
    expect_same_as_local(stem);
  }

  static SlurmCluster* cluster_;
  fs::path dir_;
};

SlurmCluster* Slurm::cluster_ = nullptr;

TEST_F(Slurm, SbatchRunsTheSceneWithItsParticipantAsAStepOfTheJob) {
  run_placed("step", "hosts: scheduler", "#SBATCH --ntasks=2\n", "srun --ntasks=1 --exact");
}

TEST_F(Slurm, HostfileNamesTheNodesOfTheAllocation) {
  write_file(dir_ / "nodes.txt", cluster_->nodes().front() + "\n");
  run_placed("listed", "hostfile: nodes.txt", "#SBATCH --ntasks=2\n", "srun --nodefile=");
}

TEST_F(Slurm, HetGroupRunsTheParticipantInItsComponentOfTheJob) {
  run_placed("het", "het_group: 1", "#SBATCH --ntasks=1\n#SBATCH hetjob\n#SBATCH --ntasks=1\n", "srun --het-group=1");
}

// Guards against: a job that reaches its time limit or is cancelled leaving a run file that
// cannot be resumed, or a resume that does not end where the whole run does.
TEST_F(Slurm, CancelledJobResumesBitIdentical) {
  auto s = placed("hosts: scheduler");
  s.spring_extra = {"delay: 0.03"};  // three seconds or more of run to cancel during
  write_file(dir_ / "cancelled.yaml", s.yaml());
  const auto h5 = (dir_ / "cancelled.h5").string();
  const auto job =
      script("cancelled", "#SBATCH --ntasks=2\n", "run " + (dir_ / "cancelled.yaml").string() + " -o " + h5);
  // The step that starts the spring may take a second or more on a loaded machine: until the
  // first checkpoint there is nothing to resume, so a cancel that came before it is tried
  // again, later.
  for (const auto wait : {500ms, 1500ms}) {
    const std::string id =
        output_of("sbatch --parsable --output=" + (dir_ / "cancelled.out").string() + " " + job.string());
    ASSERT_FALSE(id.empty());
    for (auto until = std::chrono::steady_clock::now() + 30s;
         job_output("cancelled").find("started spring") == std::string::npos &&
         std::chrono::steady_clock::now() < until;)
      std::this_thread::sleep_for(20ms);
    std::this_thread::sleep_for(wait);
    ASSERT_EQ(std::system(("scancel " + id).c_str()), 0);
    for (auto until = std::chrono::steady_clock::now() + 30s;
         !output_of("squeue -h -j " + id).empty() && std::chrono::steady_clock::now() < until;)
      std::this_thread::sleep_for(100ms);
    if (job_output("cancelled").find("nothing to resume") == std::string::npos &&
        job_output("cancelled").find("no checkpoint to resume from") == std::string::npos)
      break;
  }
  EXPECT_THAT(job_output("cancelled"), HasSubstr("cosim run --resume"));

  const auto resume = script("resumed", "#SBATCH --ntasks=2\n", "run --resume " + h5 + " -q");
  ASSERT_EQ(submit_and_wait(resume, "resumed"), 0) << job_output("resumed");
  expect_same_as_local("cancelled");
}

}  // namespace
}  // namespace cosim::testing
