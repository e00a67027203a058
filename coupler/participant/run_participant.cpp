#include "coupler/participant/run_participant.hpp"

#include <chrono>
#include <iostream>

#include "coupler/participant/seconds_since.hpp"
#include "coupler/protocol/field_message.hpp"
#include "coupler/protocol/messages.hpp"

namespace cosim::participant {
namespace {

using protocol::Array;
using protocol::Message;
using protocol::Tag;
using protocol::Type;
namespace messages = protocol::messages;

// The values of m's `which`-th array with this tag, in rows of `width`; none if m has fewer
// such arrays.
std::span<const double> row_values(const Message& m, Tag tag, std::size_t which, std::uint32_t width) {
  const auto arrays = m.all(tag);
  if (which >= arrays.size()) return {};
  const Array& a = *arrays[which];
  if (a.cols != width)
    throw protocol::ProtocolError(std::string(protocol::to_string(m.header.type)) + " carries a " +
                                  protocol::to_string(tag) + " array of " + std::to_string(a.cols) +
                                  " columns, expected " + std::to_string(width));
  return a.values;
}

std::vector<PoseRow> poses_of(const Message& m, std::size_t which) {
  return pose_rows(row_values(m, Tag::Poses, which, protocol::kPoseWidth));
}

std::vector<ForceRow> forces_of(const Message& m, std::size_t which) {
  return force_rows(row_values(m, Tag::Forces, which, protocol::kForceWidth));
}

// The arrays of what the solver provides, then Stats.
std::vector<Array> output_arrays(const Outputs& out, std::uint32_t provides, double wall) {
  std::vector<Array> arrays;
  if (scene::has(provides, scene::Data::Poses))
    arrays.push_back(Array::of(Tag::Poses, static_cast<std::uint32_t>(out.poses.size()), protocol::kPoseWidth,
                               values_of(out.poses)));
  if (scene::has(provides, scene::Data::Forces)) {
    arrays.push_back(Array::of(Tag::Forces, static_cast<std::uint32_t>(out.forces.size()), protocol::kForceWidth,
                               values_of(out.forces)));
    if (!out.responses.empty())
      arrays.push_back(Array::of(Tag::Responses, static_cast<std::uint32_t>(out.responses.size()),
                                 protocol::kResponseWidth, values_of(out.responses)));
  }
  arrays.push_back(Array::of(Tag::Stats, 1, protocol::kStatsWidth, {out.substeps, wall}));
  return arrays;
}

int serve(protocol::Client& client, Solver& solver, std::uint32_t provides, std::uint32_t needs, std::uint32_t ranks) {
  const Message init = client.hello(provides, needs, ranks);
  const auto texts = init.all(Tag::Text);
  if (texts.size() != 2) throw protocol::ProtocolError("Init must carry the scene file and text");
  const auto scene = scene::load_scene_from_string(texts[1]->bytes, texts[0]->bytes);
  const bool implicit = scene::is_implicit(scene.coupling.scheme);

  auto start = std::chrono::steady_clock::now();
  const Array* state = init.find(Tag::State);
  const Outputs initial =
      solver.initialise(scene, client.name(), poses_of(init, 0), state ? state->values : std::vector<double>{});
  std::vector<Array> ready = output_arrays(initial, provides, seconds_since(start));
  if (scene::has(needs, scene::Data::Fields))
    for (const std::string& field : solver.wanted_fields()) ready.push_back(Array::text(field));
  client.reply(messages::ready(std::move(ready)));

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
        client.reply(messages::result(w.index, w.iteration, output_arrays(out, provides, seconds_since(start))));
        break;
      }
      case Type::Checkpoint:
        client.reply(messages::state(solver.state()));
        break;
      case Type::Field:  // the coupler's writer asks for the fields at the committed time
        client.reply(messages::fields(m.header.window, protocol::field_arrays(solver.fields())));
        break;
      case Type::Commit:
        break;
      default:  // Stop
        client.reply(messages::bye());
        return 0;
    }
  }
}

}  // namespace

Inputs inputs_of(Message m) {
  std::vector<Array> fields = protocol::take_field_arrays(m.arrays);
  Inputs in{poses_of(m, 0),
            poses_of(m, 1),
            forces_of(m, 0),
            forces_of(m, 1),
            response_rows(row_values(m, Tag::Responses, 0, protocol::kResponseWidth)),
            std::nullopt};
  if (!fields.empty()) in.fields = protocol::field_frame(std::move(fields), "the fields in Advance");
  return in;
}

int run_participant(protocol::Client& client, Solver& solver, std::uint32_t provides, std::uint32_t needs,
                    std::uint32_t ranks) {
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
