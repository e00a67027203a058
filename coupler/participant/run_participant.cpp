#include "coupler/participant/run_participant.hpp"

#include <chrono>
#include <iostream>

#include "coupler/participant/seconds_since.hpp"
#include "coupler/protocol/field_message.hpp"

namespace cosim::participant {
namespace {

using protocol::Array;
using protocol::Message;
using protocol::Tag;
using protocol::Type;

std::vector<double> values_or_empty(const Message& m, Tag tag, std::size_t which = 0) {
  const auto arrays = m.all(tag);
  return which < arrays.size() ? arrays[which]->values : std::vector<double>{};
}

Message outputs_message(Type type, const Outputs& out, std::uint32_t provides, double wall) {
  Message m;
  m.header.type = type;
  const auto rows = [](const std::vector<double>& v, std::size_t cols) {
    return static_cast<std::uint32_t>(v.size() / cols);
  };
  if (scene::has(provides, scene::Data::Poses))
    m.arrays.push_back(Array::of(Tag::Poses, rows(out.poses, protocol::kPoseWidth), protocol::kPoseWidth, out.poses));
  if (scene::has(provides, scene::Data::Forces))
    m.arrays.push_back(
        Array::of(Tag::Forces, rows(out.forces, protocol::kForceWidth), protocol::kForceWidth, out.forces));
  m.arrays.push_back(Array::of(Tag::Stats, 1, 2, {out.substeps, wall}));
  return m;
}

int serve(protocol::Client& client, Solver& solver, std::uint32_t provides, std::uint32_t needs,
          std::uint32_t ranks) {
  const Message init = client.hello(provides, needs, ranks);
  const auto texts = init.all(Tag::Text);
  if (texts.size() != 2) throw protocol::ProtocolError("Init must carry the scene file and text");
  const auto scene = scene::load_scene_from_string(texts[1]->bytes, texts[0]->bytes);
  const bool implicit = scene.coupling.scheme == scene::Scheme::SerialImplicit ||
                        scene.coupling.scheme == scene::Scheme::ParallelImplicit;

  auto start = std::chrono::steady_clock::now();
  const Outputs initial = solver.initialise(scene, client.name(), values_or_empty(init, Tag::Poses),
                                            values_or_empty(init, Tag::State));
  Message ready = outputs_message(Type::Ready, initial, provides, seconds_since(start));
  if (scene::has(needs, scene::Data::Fields))
    for (const std::string& field : solver.wanted_fields()) ready.arrays.push_back(Array::text(field));
  client.reply(std::move(ready));

  std::vector<double> window_start;
  for (;;) {
    Message m = client.wait_for({Type::Advance, Type::Commit, Type::Checkpoint, Type::Field, Type::Stop});
    switch (m.header.type) {
      case Type::Advance: {
        const Window w{m.header.window, m.header.iteration, m.header.t0, m.header.t1};
        if (w.iteration > 1)
          solver.restore(window_start);
        else if (implicit)
          window_start = solver.state();
        start = std::chrono::steady_clock::now();
        const Outputs out = solver.advance(w, inputs_of(std::move(m)));
        Message result = outputs_message(Type::Result, out, provides, seconds_since(start));
        result.header.window = w.index;
        result.header.iteration = w.iteration;
        client.reply(std::move(result));
        break;
      }
      case Type::Checkpoint: {
        Message state;
        state.header.type = Type::State;
        auto s = solver.state();
        const auto n = static_cast<std::uint32_t>(s.size());
        state.arrays.push_back(Array::of(Tag::State, 1, n, std::move(s)));
        client.reply(std::move(state));
        break;
      }
      case Type::Field: {  // the coupler's writer asks for the fields at the committed time
        Message fields;
        fields.header.type = Type::Field;
        fields.header.window = m.header.window;
        fields.arrays = protocol::field_arrays(solver.fields());
        client.reply(std::move(fields));
        break;
      }
      case Type::Commit:
        break;
      default: {  // Stop
        Message bye;
        bye.header.type = Type::Bye;
        client.reply(std::move(bye));
        return 0;
      }
    }
  }
}

}  // namespace

Inputs inputs_of(Message m) {
  std::vector<Array> fields = protocol::take_field_arrays(m.arrays);
  Inputs in{values_or_empty(m, Tag::Poses, 0), values_or_empty(m, Tag::Poses, 1),
            values_or_empty(m, Tag::Forces, 0), values_or_empty(m, Tag::Forces, 1), std::nullopt};
  if (!fields.empty()) in.fields = protocol::field_frame(std::move(fields), "the fields in Advance");
  return in;
}

int run_participant(protocol::Client& client, Solver& solver, std::uint32_t provides,
                    std::uint32_t needs, std::uint32_t ranks) {
  try {
    return serve(client, solver, provides, needs, ranks);
  } catch (const protocol::Aborted& e) {
    std::cerr << client.name() << ": " << e.what() << "\n";
  } catch (const std::exception& e) {
    std::cerr << client.name() << ": " << e.what() << "\n";
    try {
      client.error(e.what());
    } catch (const std::exception&) {
      // The coupler is gone; stderr above is all we can do.
    }
  }
  return 1;
}

}  // namespace cosim::participant
