#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <zmq_addon.hpp>

#include "bench/coupler_roundtrip/cases.hpp"

namespace cosim::bench {
namespace {

// Answers each pair of frames (the input at the window start and at its end) with one
// frame of outputs computed into a buffer of its own and copied once into the frame, like
// encode() does; an empty frame ends it.
void peer(const std::string& endpoint, const std::string& name, std::size_t doubles,
          const std::optional<protocol::curve::ClientKeys>& keys) {
  zmq::context_t context;
  zmq::socket_t socket(context, zmq::socket_type::dealer);
  socket.set(zmq::sockopt::routing_id, name);
  socket.set(zmq::sockopt::linger, 1000);
  if (keys) protocol::curve::use_keys(socket, *keys);
  socket.connect(endpoint);
  std::vector<double> outputs(doubles);
  socket.send(zmq::message_t(), zmq::send_flags::none);  // lets the router learn this name
  for (std::vector<zmq::message_t> in;; in.clear()) {
    (void)zmq::recv_multipart(socket, std::back_inserter(in));
    if (in.size() != 2) break;
    answer(in[0].data(), in[1].data(), outputs);
    socket.send(zmq::message_t(outputs.data(), outputs.size() * sizeof(double)), zmq::send_flags::none);
  }
}

}  // namespace

void raw(benchmark::State& state, Case c) {
  std::vector<std::string> names;
  for (int i = 0; i < c.participants; ++i) names.push_back("peer" + std::to_string(i));
  std::optional<Keys> keys;
  if (c.transport == Transport::Curve) keys = make_keys(names);
  zmq::context_t context;
  zmq::socket_t router(context, zmq::socket_type::router);
  router.set(zmq::sockopt::linger, 0);
  if (keys) {  // encryption alone: without a ZAP handler libzmq admits any client key
    router.set(zmq::sockopt::curve_server, true);
    protocol::curve::set_key(router, ZMQ_CURVE_SECRETKEY, keys->server.own.secret_key);
  }
  router.bind(bind_address(c.transport));
  const std::string endpoint = router.get(zmq::sockopt::last_endpoint);

  std::vector<std::jthread> threads;
  for (const auto& name : names)
    threads.emplace_back(peer, endpoint, name, c.doubles, keys ? std::optional(keys->peers.at(name)) : std::nullopt);
  std::vector<zmq::message_t> frames;
  std::vector<std::string> ids;
  for (int i = 0; i < c.participants; ++i) {
    frames.clear();
    (void)zmq::recv_multipart(router, std::back_inserter(frames));
    ids.push_back(frames.front().to_string());
  }

  const std::vector<double> start(c.doubles, 1.0);
  const std::vector<double> end(c.doubles, 1.5);
  const std::size_t bytes = c.doubles * sizeof(double);
  for (auto _ : state) {
    for (const auto& id : ids) {
      router.send(zmq::buffer(id), zmq::send_flags::sndmore);
      router.send(zmq::message_t(start.data(), bytes), zmq::send_flags::sndmore);
      router.send(zmq::message_t(end.data(), bytes), zmq::send_flags::none);
    }
    for (int i = 0; i < c.participants; ++i) {
      frames.clear();
      (void)zmq::recv_multipart(router, std::back_inserter(frames));
      if (frames.size() != 2 || frames[1].size() != bytes) throw std::runtime_error("raw reply of the wrong size");
    }
  }

  for (const auto& id : ids) {
    router.send(zmq::buffer(id), zmq::send_flags::sndmore);
    router.send(zmq::message_t(), zmq::send_flags::none);
  }
  state.SetItemsProcessed(state.iterations());
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * window_bytes(c)));
}

}  // namespace cosim::bench
