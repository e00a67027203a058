// One coupled run with its participants: start them, shake hands, run the windows, record
// every committed window and checkpoint, stop them. Whatever goes wrong is thrown after the
// participants have been aborted; the caller reports it.
#pragma once

#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "coupler/estimate/run_record.hpp"
#include "coupler/output/run_file.hpp"
#include "coupler/run/exchange.hpp"
#include "coupler/run/peers.hpp"
#include "coupler/run/window.hpp"
#include "coupler/scene/plan.hpp"
#include "coupler/scene/scene.hpp"

namespace cosim::run {

class Session {
 public:
  // Everything that can be wrong with the scene is found here, before the run file is
  // touched or any process starts.
  explicit Session(scene::Scene scene);

  // Where to write, and where to start from (a checkpoint when resuming).
  void attach(output::RunFile file, std::optional<output::Checkpoint> resume_from, bool progress);
  void execute();

  const scene::Scene& scene() const { return scene_; }
  const scene::Plan& plan() const { return plan_; }
  std::vector<std::string> participant_names() const { return roles_.all(); }
  output::RunFile& file() { return *file_; }
  std::uint64_t committed() const { return committed_; }
  std::optional<std::uint64_t> checkpointed() const { return checkpointed_; }
  // This session's windows: iterations, each participant's steps and seconds, and its
  // processes' peak memory once they have stopped (the cost models learn from them).
  const estimate::RunTotals& totals() const { return totals_; }

 private:
  void announce() const;
  std::uint64_t first_window() const;
  double window_start(std::uint64_t k) const;
  void handshake(Peers& peers);
  void windows(Peers& peers);
  void record(std::uint64_t window, double time, const WindowResult& r, double wall);
  void count(const WindowResult& r);  // into totals_
  // The fields of `providers` at the start of `window` (their committed state).
  std::map<std::string, field::FieldFrame> request_fields(Peers& peers, const std::set<std::string>& providers,
                                                          std::uint64_t window, const std::string& when);
  // At the scene's fields times, every participant that provides fields sends them.
  void write_fields(Peers& peers, std::uint64_t windows_done);
  // What each participant that needs fields takes in `window`: its source's fields now,
  // only those it named in Ready.
  FieldArrays forwarded_fields(Peers& peers, std::uint64_t window);
  void checkpoint(Peers& peers, std::uint64_t next_window);

  scene::Scene scene_;
  scene::Plan plan_;
  Roles roles_;
  std::vector<std::vector<std::string>> commands_;                 // per plan_.start
  std::map<std::string, std::string> field_source_;                // participant that needs fields -> who sends them
  std::map<std::string, std::vector<std::string>> wanted_fields_;  // by name, as its Ready said; none: all
  // The frames write_fields took last, kept for forwarding at the same instant.
  struct WrittenFields {
    std::uint64_t window = std::numeric_limits<std::uint64_t>::max();
    std::map<std::string, field::FieldFrame> frames;
  } written_fields_;
  double forwarded_bytes_ = 0;  // of fields, over the windows of this session
  std::optional<output::RunFile> file_;
  std::optional<output::Checkpoint> resume_;
  bool progress_ = true;
  Exchange current_;
  std::uint64_t committed_ = 0;
  std::optional<std::uint64_t> checkpointed_;  // next window of the last checkpoint
  estimate::RunTotals totals_;
};

}  // namespace cosim::run
