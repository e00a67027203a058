// Why a run ended early. The coupler turns these into the status in the run file and the
// message on the terminal.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace cosim::run {

// A participant died, hung, sent garbage or reported an error.
struct ParticipantFailure : std::runtime_error {
  ParticipantFailure(std::string participant, std::uint64_t window, const std::string& what)
      : std::runtime_error("participant '" + participant + "' " + what + " in window " +
                           std::to_string(window)),
        participant(std::move(participant)),
        window(window) {}
  std::string participant;
  std::uint64_t window;
};

// Ctrl-C or SIGTERM reached the coupler.
struct Interrupted : std::runtime_error {
  Interrupted() : std::runtime_error("interrupted") {}
};

}  // namespace cosim::run
