// Client and Server over real sockets, ipc in a temporary folder and tcp on a free port,
// each participant in its own thread with its own ZeroMQ context.
#include <unistd.h>

#include <filesystem>
#include <future>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <zmq_addon.hpp>

#include "coupler/protocol/client.hpp"
#include "coupler/protocol/server.hpp"

namespace cosim::protocol {
namespace {

using namespace std::chrono_literals;
using ::testing::HasSubstr;

constexpr auto kWait = 5s;  // generous: only a broken test waits this long

Message make(Type type, std::vector<Array> arrays = {}) {
  Message m;
  m.header.type = type;
  m.arrays = std::move(arrays);
  return m;
}

// A bare DEALER socket under `name`, as a participant of any build would connect.
zmq::socket_t raw_peer(zmq::context_t& context, const char* name, const std::string& endpoint) {
  zmq::socket_t peer(context, zmq::socket_type::dealer);
  peer.set(zmq::sockopt::routing_id, name);
  peer.set(zmq::sockopt::linger, 0);
  peer.connect(endpoint);
  return peer;
}

class Transport : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    std::string dir = (std::filesystem::temp_directory_path() / "cosim-protocol-XXXXXX").string();
    ASSERT_NE(mkdtemp(dir.data()), nullptr);
    dir_ = dir;
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::string bind_address() const {
    return GetParam() == "ipc" ? "ipc://" + (dir_ / "coupler.sock").string() : "tcp://127.0.0.1:0";
  }

  // Waits for the participant's first message, so that the server can address it.
  static Message first(Server& server) {
    auto m = server.receive(kWait);
    if (!m) throw std::runtime_error("no first message from the participant");
    return std::move(*m);
  }

  std::filesystem::path dir_;
};

TEST_P(Transport, EndpointNamesTheBoundAddress) {
  Server server(bind_address());
  if (GetParam() == "tcp") {
    EXPECT_THAT(server.endpoint(), ::testing::StartsWith("tcp://127.0.0.1:"));
    EXPECT_THAT(server.endpoint(), ::testing::Not(::testing::EndsWith(":0")));
  } else {
    EXPECT_EQ(server.endpoint(), bind_address());
  }
}

TEST_P(Transport, HandshakeAdvanceResultStop) {
  Server server(bind_address());
  auto participant = std::async(std::launch::async, [endpoint = server.endpoint()] {
    Client client(endpoint, "fluid");
    const Message init = client.hello(0b011, 0b100, 4);
    EXPECT_EQ(init.get(Tag::Text).bytes, "scene: yes");
    const Message advance = client.wait_for({Type::Advance, Type::Stop}, kWait);
    Message result =
        make(Type::Result, {Array::of(Tag::Forces, 1, 6, {1, 2, 3, 4, 5, 6}), Array::of(Tag::Stats, 1, 2, {10, 0.5})});
    result.header.window = advance.header.window;
    result.header.t0 = advance.header.t0;
    result.header.t1 = advance.header.t1;
    client.reply(std::move(result));
    client.wait_for({Type::Stop}, kWait);
    client.reply(make(Type::Bye));
  });

  const Message hello = first(server);
  EXPECT_EQ(hello.header.type, Type::Hello);
  EXPECT_EQ(hello.header.participant, "fluid");
  EXPECT_EQ(hello.header.provides, 0b011u);
  EXPECT_EQ(hello.header.needs, 0b100u);
  EXPECT_EQ(hello.header.ranks, 4u);
  server.send("fluid", make(Type::Init, {Array::text("scene: yes")}));

  std::vector<double> poses(13, 0.0);
  poses[3] = 1.0;  // unit quaternion
  Message advance = make(Type::Advance, {Array::of(Tag::Poses, 1, 13, poses)});
  advance.header.window = 3;
  advance.header.t0 = 0.3;
  advance.header.t1 = 0.4;
  server.send("fluid", advance);
  const auto result = server.receive(kWait);
  ASSERT_TRUE(result);
  EXPECT_EQ(result->header.type, Type::Result);
  EXPECT_EQ(result->header.window, 3u);
  EXPECT_EQ(result->get(Tag::Forces).values, (std::vector<double>{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(result->get(Tag::Stats).values[0], 10.0);

  server.send("fluid", make(Type::Stop));
  const auto bye = server.receive(kWait);
  ASSERT_TRUE(bye);
  EXPECT_EQ(bye->header.type, Type::Bye);
  participant.get();
}

TEST_P(Transport, AbortIsThrownWithTheCouplersReason) {
  Server server(bind_address());
  auto participant = std::async(std::launch::async, [endpoint = server.endpoint()] {
    Client client(endpoint, "rigid");
    client.reply(make(Type::Ready));
    client.wait_for({Type::Advance}, kWait);
  });
  first(server);
  server.send("rigid", make(Type::Abort, {Array::text("fluid diverged in window 12")}));
  try {
    participant.get();
    FAIL() << "no Aborted";
  } catch (const Aborted& e) {
    EXPECT_THAT(e.what(), HasSubstr("fluid diverged in window 12"));
  }
}

TEST_P(Transport, UnexpectedTypeNamesBoth) {
  Server server(bind_address());
  auto participant = std::async(std::launch::async, [endpoint = server.endpoint()] {
    Client client(endpoint, "rigid");
    client.reply(make(Type::Ready));
    client.wait_for({Type::Advance, Type::Stop}, kWait);
  });
  first(server);
  server.send("rigid", make(Type::Commit));
  try {
    participant.get();
    FAIL() << "no ProtocolError";
  } catch (const ProtocolError& e) {
    EXPECT_THAT(e.what(), HasSubstr("expected Advance or Stop"));
    EXPECT_THAT(e.what(), HasSubstr("received Commit"));
  }
}

TEST_P(Transport, ErrorReachesTheCoupler) {
  Server server(bind_address());
  auto participant = std::async(
      std::launch::async, [endpoint = server.endpoint()] { Client(endpoint, "tracker").error("CFL number 12 > 1"); });
  const Message m = first(server);
  EXPECT_EQ(m.header.type, Type::Error);
  EXPECT_EQ(m.header.participant, "tracker");
  EXPECT_EQ(m.get(Tag::Text).bytes, "CFL number 12 > 1");
  participant.get();
}

TEST_P(Transport, ReceiveTimesOutWithNothing) {
  Server server(bind_address());
  const auto start = std::chrono::steady_clock::now();
  EXPECT_FALSE(server.receive(50ms));
  EXPECT_GE(std::chrono::steady_clock::now() - start, 45ms);
}

TEST_P(Transport, ClientWaitTimesOut) {
  Server server(bind_address());
  Client client(server.endpoint(), "fluid");
  try {
    client.wait_for({Type::Init}, 50ms);
    FAIL() << "no ProtocolError";
  } catch (const ProtocolError& e) {
    EXPECT_THAT(e.what(), HasSubstr("waited 50 ms for Init"));
  }
}

// A coupler that exits closes its end: the participant waiting on it hears so at once,
// with the coupler's address, instead of waiting out its timeout.
TEST_P(Transport, ClosedCouplerEndsTheWaitNamingIt) {
  auto server = std::make_unique<Server>(bind_address());
  const std::string endpoint = server->endpoint();
  Client client(endpoint, "fluid");
  client.reply(make(Type::Ready));
  ASSERT_TRUE(server->receive(kWait));  // connected
  server.reset();
  const auto start = std::chrono::steady_clock::now();
  try {
    client.wait_for({Type::Init}, kWait);
    FAIL() << "no ProtocolError";
  } catch (const ProtocolError& e) {
    EXPECT_THAT(e.what(), HasSubstr("participant 'fluid' lost the coupler at " + endpoint + ": the connection closed"));
  }
  EXPECT_LT(std::chrono::steady_clock::now() - start, 2s);
}

TEST_P(Transport, IdentityMustMatchHeader) {
  Server server(bind_address());
  zmq::context_t context;
  zmq::socket_t impostor = raw_peer(context, "fluid", server.endpoint());
  Message m = make(Type::Ready);
  m.header.participant = "rigid";
  zmq::send_multipart(impostor, encode(m));
  try {
    server.receive(kWait);
    FAIL() << "no PeerError";
  } catch (const PeerError& e) {
    EXPECT_EQ(e.peer, "fluid");
    EXPECT_THAT(e.what(), HasSubstr("participant 'fluid' sent a message signed 'rigid'"));
  }
}

TEST_P(Transport, UndecodableMessageNamesItsSender) {
  Server server(bind_address());
  zmq::context_t context;
  zmq::socket_t peer = raw_peer(context, "fluid", server.endpoint());
  peer.send(zmq::str_buffer("GET / HTTP/1.0"));
  try {
    server.receive(kWait);
    FAIL() << "no PeerError";
  } catch (const PeerError& e) {
    EXPECT_EQ(e.peer, "fluid");
    EXPECT_THAT(e.what(), HasSubstr("participant 'fluid' sent a message the coupler cannot read: not a cosim message"));
  }
}

TEST_P(Transport, AnEarlierVersionsParticipantIsAnsweredInItsVersion) {
  Server server(bind_address());
  zmq::context_t context;
  zmq::socket_t peer = raw_peer(context, "rigid", server.endpoint());
  Message hello = make(Type::Hello);
  hello.header.participant = "rigid";
  hello.header.version = 3;  // before Responses arrays
  zmq::send_multipart(peer, encode(hello));
  EXPECT_EQ(first(server).header.version, 3);

  server.send("rigid", make(Type::Advance, {Array::of(Tag::Forces, 1, kForceWidth, std::vector<double>(6, 1.0))}));
  std::vector<zmq::message_t> frames;
  peer.set(zmq::sockopt::rcvtimeo, static_cast<int>(std::chrono::milliseconds(kWait).count()));
  ASSERT_TRUE(zmq::recv_multipart(peer, std::back_inserter(frames)));
  const Message advance = decode(frames);
  EXPECT_EQ(advance.header.version, 3);
  EXPECT_EQ(advance.get(Tag::Forces).values, std::vector<double>(6, 1.0));

  try {
    server.send(
        "rigid",
        make(Type::Advance, {Array::of(Tag::Responses, 1, kResponseWidth, std::vector<double>(kResponseWidth, 0.0))}));
    FAIL() << "no PeerError";
  } catch (const PeerError& e) {
    EXPECT_EQ(e.peer, "rigid");
    EXPECT_THAT(e.what(), HasSubstr("'rigid' speaks protocol version 3, in which the Advance message"));
    EXPECT_THAT(e.what(), HasSubstr("(Responses) came with protocol version 4"));
  }
}

TEST_P(Transport, SendingToUnknownParticipantThrows) {
  Server server(bind_address());
  try {
    server.send("nobody", make(Type::Stop));
    FAIL() << "no PeerError";
  } catch (const PeerError& e) {
    EXPECT_EQ(e.peer, "nobody");
    EXPECT_THAT(e.what(), HasSubstr("'nobody' is not connected"));
  }
}

INSTANTIATE_TEST_SUITE_P(IpcAndTcp, Transport, ::testing::Values("ipc", "tcp"),
                         [](const auto& info) { return info.param; });

TEST(Transport, StarPortPicksAFreePortToo) {
  Server server("tcp://127.0.0.1:*");
  EXPECT_THAT(server.endpoint(), ::testing::Not(::testing::EndsWith(":*")));
}

TEST(Transport, BindFailureIsAProtocolError) { EXPECT_THROW(Server("bogus://nowhere"), ProtocolError); }

TEST(ClientEnvironment, AbsentMeansNotStartedByTheCoupler) {
  unsetenv(kEndpointEnv);
  unsetenv(kParticipantEnv);
  EXPECT_FALSE(Client::from_environment());
}

TEST(ClientEnvironment, HalfSetIsAnError) {
  setenv(kEndpointEnv, "tcp://127.0.0.1:5555", 1);
  unsetenv(kParticipantEnv);
  EXPECT_THROW(Client::from_environment(), ProtocolError);
}

TEST(ClientEnvironment, HeartbeatMustBeSeconds) {
  setenv(kEndpointEnv, "tcp://127.0.0.1:5555", 1);
  setenv(kParticipantEnv, "tracker", 1);
  for (const char* bad : {"", "ten", "0", "-1", "1s"}) {
    setenv(kHeartbeatEnv, bad, 1);
    EXPECT_THROW(Client::from_environment(), ProtocolError) << bad;
  }
  setenv(kHeartbeatEnv, "2.5", 1);
  EXPECT_TRUE(Client::from_environment());
  unsetenv(kHeartbeatEnv);
}

TEST(ClientEnvironment, ConnectsUnderItsName) {
  Server server("tcp://127.0.0.1:0");
  setenv(kEndpointEnv, server.endpoint().c_str(), 1);
  setenv(kParticipantEnv, "tracker", 1);
  auto client = Client::from_environment();
  ASSERT_TRUE(client);
  EXPECT_EQ(client->name(), "tracker");
  client->reply(make(Type::Ready));
  const auto m = server.receive(kWait);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->header.participant, "tracker");
}

TEST(ClientName, InvalidNameIsRefusedAtOnce) {
  EXPECT_THROW(Client("tcp://127.0.0.1:5555", "two words"), ProtocolError);
}

}  // namespace
}  // namespace cosim::protocol
