#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "bench/coupler_roundtrip/cases.hpp"
#include "coupler/protocol/client.hpp"
#include "coupler/protocol/messages.hpp"
#include "coupler/protocol/server.hpp"

namespace cosim::bench {
namespace {

using namespace protocol;
constexpr std::chrono::seconds kTimeout(30);

// Answers every Advance as a solver would after its substeps: its outputs, computed into a
// buffer of its own, and its Stats.
void participant(const std::string& endpoint, const std::string& name, const std::optional<curve::ClientKeys>& keys) {
  Client client(endpoint, name, keys);
  client.hello(0, 0);
  std::vector<double> outputs;
  for (;;) {
    const Message in = client.wait_for({Type::Advance, Type::Stop}, kTimeout);
    if (in.header.type == Type::Stop) break;
    if (in.arrays.size() != 2 || in.arrays[0].values.size() != in.arrays[1].values.size())
      throw std::runtime_error("Advance without the input at the window start and end");
    const Array& start = in.arrays[0];
    outputs.resize(start.values.size());
    answer(start.values.data(), in.arrays[1].values.data(), outputs);
    // Copies the outputs into the message, as run_participant does with a solver's.
    client.reply(messages::result(
        in.header.window, in.header.iteration,
        {Array::of(start.tag, start.rows, start.cols, outputs), Array::of(Tag::Stats, 1, kStatsWidth, {1.0, 0.0})}));
  }
  client.reply(messages::bye());
}

Message expect(Server& server, Type type) {
  auto m = server.receive(kTimeout);
  if (!m) throw std::runtime_error(std::string("no ") + to_string(type) + " within the timeout");
  if (m->header.type != type)
    throw std::runtime_error(std::string("expected ") + to_string(type) + ", received " + to_string(m->header.type));
  return std::move(*m);
}

}  // namespace

void window(benchmark::State& state, Case c) {
  std::vector<std::string> names;
  for (int i = 0; i < c.participants; ++i) names.push_back("solver" + std::to_string(i));
  std::optional<Keys> keys;
  if (c.transport == Transport::Curve) keys = make_keys(names);
  Server server(bind_address(c.transport), ServerOptions{keys ? std::optional(keys->server) : std::nullopt, {}});
  std::vector<std::jthread> threads;
  for (const auto& name : names)
    threads.emplace_back(participant, server.endpoint(), name,
                         keys ? std::optional(keys->peers.at(name)) : std::nullopt);
  for (int i = 0; i < c.participants; ++i) expect(server, Type::Hello);
  // An Init without a scene: these participants read none.
  Message init;
  init.header.type = Type::Init;
  for (const auto& name : names) server.send(name, init);

  // The coupler sends each input twice, at the window start and at its end.
  Message advance = messages::advance(0, 1, 0.0, 0.0, {payload(c.doubles), payload(c.doubles)});
  for (double& v : advance.arrays.back().values) v += 0.5;
  for (auto _ : state) {
    for (const auto& name : names) server.send(name, advance);
    for (int i = 0; i < c.participants; ++i) {
      const Message result = expect(server, Type::Result);
      if (result.arrays.size() != 2 || result.arrays.front().values.size() != c.doubles ||
          result.get(Tag::Stats).values.size() != 2)
        throw std::runtime_error("result of the wrong size");
    }
    advance.header.window += 1;
    advance.header.t0 = advance.header.t1;
    advance.header.t1 += 0.01;
  }

  for (const auto& name : names) server.send(name, messages::stop());
  for (int i = 0; i < c.participants; ++i) expect(server, Type::Bye);
  state.SetItemsProcessed(state.iterations());
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * window_bytes(c)));
}

}  // namespace cosim::bench
