// Warnings that can come in floods, such as a client knocking again and again without the
// run's key: each distinct warning is said at most once a second, its repeats in between
// only counted, and the count is said with its next line or when the run ends. A scanner
// hammering the port must not drown the log, nor hide a different warning.
#pragma once

#include <chrono>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace cosim::run {

class WarningRate {
 public:
  using clock = std::chrono::steady_clock;

  explicit WarningRate(std::chrono::milliseconds period = std::chrono::seconds(1)) : period_(period) {}

  // The line to log for `text` at `now`, with the count of its repeats held back since it
  // was last said; nothing while the period since then has not passed.
  std::optional<std::string> admit(const std::string& text, clock::time_point now = clock::now());
  // A line for each warning with repeats held back: for the end of the run.
  std::vector<std::string> held_back();

 private:
  struct Seen {
    clock::time_point said;
    long held = 0;
  };
  std::chrono::milliseconds period_;
  std::map<std::string, Seen> seen_;
};

}  // namespace cosim::run
