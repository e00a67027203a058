// Two hosts on one machine: the coupler in one network namespace, the spring in another,
// joined by a veth pair, over tcp with CURVE on that link; then faults on the link. Skipped,
// with the reason, where the machine cannot make network namespaces (not root).
#include <fcntl.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sched.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <fstream>
#include <regex>
#include <sstream>
#include <thread>

#include <zmq_addon.hpp>

#include "coupler/protocol/curve.hpp"
#include "coupler/protocol/message.hpp"
#include "tests/integration/cosim_process.hpp"
#include "tests/integration/h5_read.hpp"
#include "tests/integration/network_namespaces.hpp"
#include "tests/integration/oscillator_scene.hpp"

namespace cosim::testing {
namespace {

using namespace std::chrono_literals;
using ::testing::HasSubstr;
namespace fs = std::filesystem;
namespace curve = protocol::curve;

constexpr const char* kIp = "/usr/sbin/ip";

const std::vector<std::string> kSeries{"/bodies/m1/time", "/bodies/m1/position", "/bodies/m1/force",
                                       "/coupling/iterations"};

void expect_same_series(const fs::path& a, const fs::path& b) {
  for (const auto& series : kSeries) EXPECT_EQ(read_series(a, series).values, read_series(b, series).values) << series;
}

class TwoHosts : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!net_.made()) GTEST_SKIP() << net_.why();
    if (access(kIp, X_OK) != 0) GTEST_SKIP() << kIp << " is missing (iproute2)";
    dir_ = scratch_dir(::testing::UnitTest::GetInstance()->current_test_info()->name());
    // The same run on one host, by ipc: what every run across the link must give.
    ASSERT_EQ(run_scene_text(dir_, scene(false).yaml(), "local").exit_code, 0);
  }

  // 100 windows, checkpoints every 7; across hosts the coupler listens on the first
  // namespace's address and the spring is started inside the second one.
  OscillatorScene scene(bool across) const {
    OscillatorScene s;
    s.checkpoint_every = 7;
    s.heartbeat = 1.5;
    s.timeout = 30;  // far beyond: the heartbeat must be what notices a broken link
    if (!across) return s;
    s.transport = "tcp";
    s.interface = NamespacePair::kFirstAddress;
    const auto spring = fs::read_symlink("/proc/self/exe").parent_path() / "cosim-test-oscillator-spring";
    s.spring_command = "[" + std::string(kIp) + ", netns, exec, " + net_.second() + ", " + spring.string() + "]";
    return s;
  }

  // `cosim run` of the scene inside the first namespace.
  std::unique_ptr<CosimProcess> start(const OscillatorScene& s, const std::string& stem) const {
    write_file(dir_ / (stem + ".yaml"), s.yaml());
    return std::make_unique<CosimProcess>(run_args(dir_, stem), NamespacePair::path(net_.first()));
  }

  // start() of the scene slowed to a second or more of run, once its windows are under way:
  // a run to break things during.
  std::unique_ptr<CosimProcess> running(OscillatorScene s, const std::string& stem) const {
    s.spring_extra = {"delay: 0.01"};
    auto cosim = start(s, stem);
    wait_for(*cosim, "started spring");
    std::this_thread::sleep_for(300ms);
    return cosim;
  }

  static void wait_for(const CosimProcess& cosim, const std::string& text) {
    for (auto until = std::chrono::steady_clock::now() + 20s; std::chrono::steady_clock::now() < until;) {
      if (cosim.output().find(text) != std::string::npos) return;
      std::this_thread::sleep_for(10ms);
    }
    FAIL() << "cosim never printed " << text << ":\n" << cosim.output();
  }

  NamespacePair net_;
  fs::path dir_;
};

TEST_F(TwoHosts, CurveAcrossTheLinkGivesTheLocalAnswer) {
  const auto r = start(scene(true), "across")->wait();
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("listening on tcp://10.231.0.1:"));
  expect_same_series(dir_ / "local.h5", dir_ / "across.h5");
}

// Guards against: a link that breaks for longer than the heartbeat hanging the run, going
// unnamed, leaving the participant waiting, or a resume that does not end identical.
TEST_F(TwoHosts, LinkDownLongerThanTheHeartbeatEndsResumableAndResumeIsIdentical) {
  const auto cosim = running(scene(true), "broken");
  ASSERT_EQ(net_.in_second("ip link set LINK down"), 0);
  const auto down_at = std::chrono::steady_clock::now();
  const auto r = cosim->wait();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - down_at).count();
  std::cout << "a link down ended the run after " << seconds << " s (heartbeat 1.5 s)\n";
  ASSERT_EQ(net_.in_second("ip link set LINK up"), 0);
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("participant 'spring' lost its connection to the coupler"));
  EXPECT_THAT(r.output, HasSubstr("cosim run --resume"));
  EXPECT_LT(seconds, 1.5 + 2.0 + 1.5);  // the heartbeat, then 2 s for the participants to stop

  const auto resumed =
      CosimProcess({"run", "--resume", (dir_ / "broken.h5").string(), "-q"}, NamespacePair::path(net_.first())).wait();
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  expect_same_series(dir_ / "local.h5", dir_ / "broken.h5");
}

// The run's wall seconds across the link as it is.
double timed_run(const std::unique_ptr<CosimProcess>& cosim) {
  const auto begin = std::chrono::steady_clock::now();
  const auto r = cosim->wait();
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
}

// A narrow link (a token bucket of 1 Mbit/s) slows the run, which finishes with the same
// answer.
TEST_F(TwoHosts, NarrowLinkSlowsTheRunButNotItsAnswer) {
  const double wide = timed_run(start(scene(true), "wide"));
  ASSERT_EQ(net_.in_second("tc qdisc add dev LINK root tbf rate 1mbit burst 32kbit latency 400ms"), 0);
  const double narrow = timed_run(start(scene(true), "narrow"));
  std::cout << "the run took " << wide << " s, " << narrow << " s on a 1 Mbit/s link\n";
  EXPECT_GT(narrow, wide);
  expect_same_series(dir_ / "local.h5", dir_ / "narrow.h5");
}

// Loss on the link (5 % of the packets that reach the participant's host dropped, by an
// nftables rule) slows the run, which finishes with the same answer.
TEST_F(TwoHosts, LossSlowsTheRunButNotItsAnswer) {
  if (access("/usr/sbin/nft", X_OK) != 0) GTEST_SKIP() << "/usr/sbin/nft is missing (Debian's nftables)";
  const double clean = timed_run(start(scene(true), "clean"));
  ASSERT_EQ(net_.in_second("nft 'add table inet loss; add chain inet loss in { type filter hook input priority 0; }; "
                           "add rule inet loss in iifname LINK numgen random mod 100 < 5 drop'"),
            0);
  const double lossy = timed_run(start(scene(true), "lossy"));
  std::cout << "the run took " << clean << " s, " << lossy << " s with 5 % loss\n";
  EXPECT_GT(lossy, clean);
  expect_same_series(dir_ / "local.h5", dir_ / "lossy.h5");
}

// Delay on the link (5 ms each way, netem) slows the run, which finishes with the same
// answer. Needs the kernel's netem qdisc (sch_netem).
TEST_F(TwoHosts, DelaySlowsTheRunButNotItsAnswer) {
  const double clean = timed_run(start(scene(true), "clean"));
  if (net_.in_second("tc qdisc add dev LINK root netem delay 5ms") != 0)
    GTEST_SKIP() << "this kernel has no netem qdisc (sch_netem): a delay cannot be made";
  const double delayed = timed_run(start(scene(true), "delayed"));
  std::cout << "the run took " << clean << " s, " << delayed << " s with 5 ms delay\n";
  EXPECT_GT(delayed, clean);
  expect_same_series(dir_ / "local.h5", dir_ / "delayed.h5");
}

// Every process of the participant's host killed at once: the run names it and ends
// resumable.
TEST_F(TwoHosts, ParticipantsHostKilledWholeIsNamed) {
  const auto cosim = running(scene(true), "killed");
  ASSERT_EQ(std::system(
                ("for p in $(" + std::string(kIp) + " netns pids " + net_.second() + "); do kill -9 $p; done").c_str()),
            0);
  const auto r = cosim->wait();
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("participant 'spring'"));
  EXPECT_THAT(r.output, HasSubstr("cosim run --resume"));
}

// A process on the participant's host that read the spring's public key (not its secret
// one) from its environment is refused; the run finishes unharmed.
TEST_F(TwoHosts, StolenPublicKeyFromTheParticipantsHostIsRefused) {
  const auto cosim = running(scene(true), "knocked");
  const pid_t spring = child_pid(cosim->pid(), "cosim-test-oscillator-spring");
  ASSERT_GT(spring, 0);
  std::map<std::string, std::string> env;
  {
    std::ifstream in("/proc/" + std::to_string(spring) + "/environ");
    for (std::string entry; std::getline(in, entry, '\0');)
      if (const auto eq = entry.find('='); eq != std::string::npos) env[entry.substr(0, eq)] = entry.substr(eq + 1);
  }
  std::thread thief([&] {
    const int ns = open(NamespacePair::path(net_.second()).c_str(), O_RDONLY | O_CLOEXEC);
    if (ns < 0 || setns(ns, CLONE_NEWNET) != 0) return;
    close(ns);
    zmq::context_t context;  // its I/O thread starts here, inside the namespace
    zmq::socket_t k(context, zmq::socket_type::dealer);
    k.set(zmq::sockopt::routing_id, "spring");
    k.set(zmq::sockopt::linger, 0);
    curve::use_keys(
        k, curve::ClientKeys{env[curve::kServerKeyEnv], {env[curve::kPublicKeyEnv], curve::make_keypair().secret_key}});
    k.connect(env["COSIM_ENDPOINT"]);
    std::this_thread::sleep_for(500ms);
  });
  thief.join();
  const auto r = cosim->wait();
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("refused a connection"));
  expect_same_series(dir_ / "local.h5", dir_ / "knocked.h5");
}

}  // namespace
}  // namespace cosim::testing
