// One factory per message type: each takes exactly what that message carries and fills
// its header as docs/protocol.md describes (fields it does not name are left at their
// defaults). The participant's name is filled in by whoever sends (Client::reply,
// Server::send).
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "coupler/protocol/message.hpp"

namespace cosim::protocol::messages {

// Participant -> coupler.
Message hello(std::uint32_t provides, std::uint32_t needs, std::uint32_t ranks);
// The outputs at t0 (Poses and/or Forces, Stats), then the Text names of the fields it uses.
Message ready(std::vector<Array> arrays);
// The outputs at t1 of the window's iteration, then Stats.
Message result(std::uint64_t window, std::uint32_t iteration, std::vector<Array> arrays);
Message state(std::vector<double> values);
// The answer to a Field request: the arrays of a frame (field_message.hpp).
Message fields(std::uint64_t window, std::vector<Array> arrays);
Message error(std::string_view text);
Message bye();

// Coupler -> participant. Init's window is the first one, [t0, t1] that window's start to
// the run's end; its state is given when resuming.
Message init(std::uint64_t window, double t0, double t1, std::string_view scene_file, std::string_view scene_text,
             Array poses, std::optional<std::vector<double>> state);
// The inputs of the window's iteration: each one's value at t0 then at t1, then any fields.
Message advance(std::uint64_t window, std::uint32_t iteration, double t0, double t1, std::vector<Array> inputs);
Message commit(std::uint64_t window);
// `window`: the number of windows committed.
Message checkpoint(std::uint64_t window);
// Asks for the fields at `time`, the start of `window`.
Message field_request(std::uint64_t window, double time);
Message stop();
Message abort(std::string_view reason);

}  // namespace cosim::protocol::messages
