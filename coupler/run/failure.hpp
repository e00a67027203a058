// Why a run ended early. The coupler turns these into the status in the run file and the
// message on the terminal.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace cosim::run {

// A participant died, hung, sent garbage or reported an error. `when` says where the run
// was: "in window 56 (t = 0.56 .. 0.57 s)", "during start-up", ...
struct ParticipantFailure : std::runtime_error {
  ParticipantFailure(std::string participant, const std::string& problem, const std::string& when)
      : std::runtime_error("participant '" + participant + "' " + problem + " " + when),
        participant(std::move(participant)) {}
  std::string participant;
};

std::string in_window(std::uint64_t k, double t0, double t1);

// Ctrl-C or SIGTERM reached the coupler.
struct Interrupted : std::runtime_error {
  Interrupted() : std::runtime_error("interrupted") {}
};

}  // namespace cosim::run
