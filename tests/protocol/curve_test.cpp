// The coupler's socket with CURVE on 127.0.0.2, an address other than the default: only the
// run's participants get in, each under its own name; everyone else is refused, said so,
// and the participants' conversation goes on. Connections end in a heartbeat's time.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <random>
#include <thread>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <zmq_addon.hpp>

#include "coupler/protocol/client.hpp"
#include "coupler/protocol/server.hpp"

namespace cosim::protocol {
namespace {

using namespace std::chrono_literals;
using ::testing::AnyOf;
using ::testing::Contains;
using ::testing::HasSubstr;

constexpr auto kWait = 5s;  // generous: only a broken test waits this long

Message make(Type type, const std::string& from = "mass") {
  Message m;
  m.header.type = type;
  m.header.participant = from;
  return m;
}

struct Coupler {
  curve::ServerKeys keys{curve::make_keypair(), {}};
  curve::ClientKeys mass{keys.own.public_key, curve::make_keypair()};
  std::optional<Server> server;

  explicit Coupler(std::chrono::milliseconds heartbeat = 0ms) {
    keys.participants.emplace(mass.own.public_key, "mass");
    server.emplace("tcp://127.0.0.2:*", ServerOptions{keys, heartbeat});
  }

  // Receives until a message comes, collecting what was refused meanwhile.
  Message next(std::vector<std::string>& refusals) {
    const auto deadline = std::chrono::steady_clock::now() + kWait;
    while (std::chrono::steady_clock::now() < deadline) {
      auto m = server->receive(20ms);
      for (auto& r : server->refusals()) refusals.push_back(std::move(r));
      if (m) return std::move(*m);
    }
    throw std::runtime_error("no message");
  }

  // Polls for `wait` so that late refusals get logged.
  std::vector<std::string> refusals_within(std::chrono::milliseconds wait) {
    std::vector<std::string> out;
    const auto deadline = std::chrono::steady_clock::now() + wait;
    while (std::chrono::steady_clock::now() < deadline) {
      EXPECT_FALSE(server->receive(20ms));
      for (auto& r : server->refusals()) out.push_back(std::move(r));
    }
    return out;
  }
};

// A raw DEALER: no key, or the keys given.
zmq::socket_t dealer(zmq::context_t& context, const std::string& name, const std::optional<curve::ClientKeys>& keys) {
  zmq::socket_t s(context, zmq::socket_type::dealer);
  s.set(zmq::sockopt::routing_id, name);
  s.set(zmq::sockopt::linger, 0);
  if (keys) curve::use_keys(s, *keys);
  return s;
}

// Writes bytes to the endpoint over a plain TCP connection and closes it.
void send_raw(const std::string& endpoint, const std::string& bytes) {
  const auto colon = endpoint.rfind(':');
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<std::uint16_t>(std::stoi(endpoint.substr(colon + 1))));
  inet_pton(AF_INET, endpoint.substr(6, colon - 6).c_str(), &address.sin_addr);
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  ASSERT_GE(fd, 0);
  if (connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0)
    (void)!write(fd, bytes.data(), bytes.size());
  close(fd);
}

TEST(Curve, ParticipantWithItsKeysTalksToTheCoupler) {
  Coupler run;
  EXPECT_THAT(run.server->endpoint(), ::testing::StartsWith("tcp://127.0.0.2:"));
  Client mass(run.server->endpoint(), "mass", run.mass);
  mass.reply(make(Type::Hello));
  std::vector<std::string> refusals;
  EXPECT_EQ(run.next(refusals).header.participant, "mass");
  run.server->send("mass", make(Type::Init));
  EXPECT_EQ(mass.wait_for({Type::Init}, kWait).header.type, Type::Init);
  EXPECT_TRUE(refusals.empty());
}

// Guards against: a client without the run's keys, or with a name its key does not carry,
// reaching the coupler; and any of them, or garbage, disturbing the participants.
TEST(Curve, ForeignClientsAreRefusedAndSaidSo) {
  Coupler run;
  const auto endpoint = run.server->endpoint();
  zmq::context_t context;
  std::vector<zmq::socket_t> foreign;
  foreign.push_back(dealer(context, "mass", std::nullopt));  // no key
  foreign.push_back(dealer(context, "mass", curve::ClientKeys{run.keys.own.public_key, curve::make_keypair()}));
  foreign.push_back(
      dealer(context, "mass", curve::ClientKeys{curve::make_keypair().public_key, curve::make_keypair()}));
  foreign.push_back(dealer(context, "intruder", run.mass));  // the right key, another name
  for (auto& s : foreign) {
    s.connect(endpoint);
    zmq::send_multipart(s, encode(make(Type::Hello, s.get(zmq::sockopt::routing_id))));
  }
  send_raw(endpoint, "GET / HTTP/1.0\r\n\r\n");
  const auto refusals = run.refusals_within(1s);
  // Without a key the client may hang up first, on seeing the coupler's mechanism: then the
  // coupler sees the handshake end, not its reason.
  EXPECT_THAT(refusals,
              Contains(AnyOf(HasSubstr("it does not use CURVE (no key)"), HasSubstr("its handshake failed"))));
  EXPECT_THAT(refusals, Contains(HasSubstr("refused a connection from 127.0.0.1: its key is not one of this run's")));
  EXPECT_THAT(refusals, Contains(HasSubstr("it does not hold the coupler's public key of this run")));
  EXPECT_THAT(refusals, Contains(HasSubstr("a client holding the key of 'mass' under the name 'intruder'")));

  Client mass(endpoint, "mass", run.mass);
  mass.reply(make(Type::Hello));
  std::vector<std::string> more;
  const auto m = run.next(more);
  EXPECT_EQ(m.header.participant, "mass");
  EXPECT_EQ(m.header.type, Type::Hello);
}

// Guards against: a malformed or hostile handshake crashing or wedging the coupler.
TEST(Curve, FuzzedHandshakesNeverHurtTheCoupler) {
  Coupler run;
  const auto endpoint = run.server->endpoint();
  // The start of a real ZMTP 3.0 CURVE greeting, mutated.
  std::string greeting("\xff\0\0\0\0\0\0\0\x01\x7f\x03\x00CURVE", 17);
  greeting.resize(64, '\0');
  std::mt19937 random(24);
  for (int i = 0; i < 300; ++i) {
    std::string bytes = greeting.substr(0, 1 + random() % greeting.size());
    for (int flips = random() % 4; flips > 0; --flips) bytes[random() % bytes.size()] = static_cast<char>(random());
    const auto tail = random() % 200;
    for (std::size_t k = 0; k < tail; ++k) bytes.push_back(static_cast<char>(random()));
    send_raw(endpoint, bytes);
    if (i % 50 == 0) (void)run.server->receive(0ms);  // let the handshakes fail meanwhile
  }
  (void)run.refusals_within(200ms);
  Client mass(endpoint, "mass", run.mass);
  mass.reply(make(Type::Hello));
  std::vector<std::string> refusals;
  EXPECT_EQ(run.next(refusals).header.type, Type::Hello);
}

// A connection that ends is reported under the name its messages came with (a stopped,
// silent participant is dropped by the heartbeat: tests/integration stops one).
TEST(Curve, EndedConnectionIsReportedByName) {
  Coupler run(400ms);
  auto mass = std::make_unique<Client>(run.server->endpoint(), "mass", run.mass);
  mass->reply(make(Type::Hello));
  std::vector<std::string> refusals;
  (void)run.next(refusals);
  mass.reset();
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::string> lost;
  while (lost.empty() && std::chrono::steady_clock::now() - start < kWait) {
    (void)run.server->receive(20ms);
    lost = run.server->lost();
  }
  EXPECT_EQ(lost, std::vector<std::string>{"mass"});
}

TEST(Curve, CouplerKeyFileIsReadableByItsUserAlone) {
  const auto dir = std::filesystem::temp_directory_path() / ("cosim-curve-" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const auto pair = curve::make_keypair();
  curve::write_keypair(dir / "coupler.key", pair);
  struct stat st {};
  ASSERT_EQ(stat((dir / "coupler.key").c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0600u);
  EXPECT_THROW(curve::write_keypair(dir / "coupler.key", pair), ProtocolError);  // never reused
  std::filesystem::remove_all(dir);
}

TEST(Curve, KeysComeFromTheEnvironmentAllOrNone) {
  for (const char* name : {curve::kServerKeyEnv, curve::kPublicKeyEnv, curve::kSecretKeyEnv}) unsetenv(name);
  EXPECT_FALSE(curve::from_environment());
  const curve::ClientKeys keys{curve::make_keypair().public_key, curve::make_keypair()};
  for (const auto& [name, value] : curve::environment(keys)) setenv(name.c_str(), value.c_str(), 1);
  const auto read = curve::from_environment();
  ASSERT_TRUE(read);
  EXPECT_EQ(read->own.secret_key, keys.own.secret_key);
  unsetenv(curve::kSecretKeyEnv);
  EXPECT_THROW(curve::from_environment(), ProtocolError);
  for (const char* name : {curve::kServerKeyEnv, curve::kPublicKeyEnv}) unsetenv(name);
}

}  // namespace
}  // namespace cosim::protocol
