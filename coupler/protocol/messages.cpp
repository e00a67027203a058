#include "coupler/protocol/messages.hpp"

#include <utility>

namespace cosim::protocol::messages {
namespace {

// A message of `type` about `window`, the rest of its header at the defaults.
Message of(Type type, std::uint64_t window = 0, std::vector<Array> arrays = {}) {
  Message m;
  m.header.type = type;
  m.header.window = window;
  m.arrays = std::move(arrays);
  return m;
}

Array state_array(std::vector<double> values) {
  const auto n = static_cast<std::uint32_t>(values.size());
  return Array::of(Tag::State, 1, n, std::move(values));
}

}  // namespace

Message hello(std::uint32_t provides, std::uint32_t needs, std::uint32_t ranks) {
  Message m = of(Type::Hello);
  m.header.provides = provides;
  m.header.needs = needs;
  m.header.ranks = ranks;
  return m;
}

Message ready(std::vector<Array> arrays) { return of(Type::Ready, 0, std::move(arrays)); }

Message result(std::uint64_t window, std::uint32_t iteration, std::vector<Array> arrays) {
  Message m = of(Type::Result, window, std::move(arrays));
  m.header.iteration = iteration;
  return m;
}

Message state(std::vector<double> values) { return of(Type::State, 0, {state_array(std::move(values))}); }

Message fields(std::uint64_t window, std::vector<Array> arrays) { return of(Type::Field, window, std::move(arrays)); }

Message error(std::string_view text) { return of(Type::Error, 0, {Array::text(text)}); }

Message bye() { return of(Type::Bye); }

Message init(std::uint64_t window, double t0, double t1, std::string_view scene_file, std::string_view scene_text,
             Array poses, std::optional<std::vector<double>> state) {
  Message m = of(Type::Init, window, {Array::text(scene_file), Array::text(scene_text), std::move(poses)});
  if (state) m.arrays.push_back(state_array(std::move(*state)));
  m.header.t0 = t0;
  m.header.t1 = t1;
  return m;
}

Message advance(std::uint64_t window, std::uint32_t iteration, double t0, double t1, std::vector<Array> inputs) {
  Message m = of(Type::Advance, window, std::move(inputs));
  m.header.iteration = iteration;
  m.header.t0 = t0;
  m.header.t1 = t1;
  return m;
}

Message commit(std::uint64_t window) { return of(Type::Commit, window); }

Message checkpoint(std::uint64_t window) { return of(Type::Checkpoint, window); }

Message field_request(std::uint64_t window, double time) {
  Message m = of(Type::Field, window);
  m.header.t0 = m.header.t1 = time;
  return m;
}

Message stop() { return of(Type::Stop); }

Message abort(std::string_view reason) { return of(Type::Abort, 0, {Array::text(reason)}); }

}  // namespace cosim::protocol::messages
