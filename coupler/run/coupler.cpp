#include "coupler/run/coupler.hpp"

#include <spdlog/spdlog.h>

#include <chrono>
#include <iostream>

#include "cosim_git_hash.hpp"
#include "coupler/estimate/estimate.hpp"
#include "coupler/estimate/program_work.hpp"
#include "coupler/launcher/process.hpp"
#include "coupler/output/run_file.hpp"
#include "coupler/run/failure.hpp"
#include "coupler/run/interrupt.hpp"
#include "coupler/run/session.hpp"

namespace cosim::run {
namespace fs = std::filesystem;
namespace {

using clock = std::chrono::steady_clock;

// Each program reads its section before anything starts, as `cosim check` has them do, and
// their work reports give the run's estimate. Empty if one refused (it said why).
std::optional<std::map<std::string, estimate::ProgramWork>> read_sections(const scene::Scene& scene,
                                                                          const scene::Plan& plan) {
  auto sections = estimate::read_sections(scene, plan.start);
  if (!sections.refused.empty()) {
    spdlog::error("{}", estimate::refused_message(scene, sections.refused));
    return std::nullopt;
  }
  std::cout << estimate::estimate_here(scene, plan.start, sections.work, COSIM_GIT_HASH) << std::endl;
  return std::move(sections.work);
}

// A finished run teaches the cost models of this host what it took; a failure to record it
// costs only the next estimate's accuracy.
void learn(const scene::Scene& scene, const std::map<std::string, estimate::ProgramWork>& work,
           estimate::RunTotals totals, double wall, const fs::path& run_file) {
  try {
    totals.wall_seconds = wall;
    totals.disk_bytes = static_cast<double>(fs::file_size(run_file));
    estimate::CostStore::update(estimate::CostStore::default_path(), [&](estimate::CostStore& store) {
      store.add(estimate::run_record(scene, work, totals, COSIM_GIT_HASH));
    });
  } catch (const std::exception& e) {
    spdlog::warn("the run's cost was not recorded for later estimates: {}", e.what());
  }
}

}  // namespace

int run(const RunRequest& request) {
  install_interrupt_handlers();
  launcher::adopt_orphans();
  const auto wall_start = clock::now();
  const auto wall = [&] { return std::chrono::duration<double>(clock::now() - wall_start).count(); };

  std::optional<Session> session;
  fs::path path;
  std::map<std::string, estimate::ProgramWork> work;  // a new run's; a resumed run does not learn
  if (request.resume) {
    // Validate what the file holds before resume() writes anything to it.
    path = *request.resume;
    const auto summary = output::RunFile::peek(path);
    if (!summary.has_checkpoint) throw std::runtime_error(path.string() + " has no checkpoint: it cannot be resumed");
    session.emplace(scene::load_scene_from_string(summary.info.scene_text, summary.info.scene_file));
    auto file = output::RunFile::resume(path, COSIM_GIT_HASH);
    auto from = file.checkpoint();
    spdlog::info("resuming {} from window {} (t = {} s)", path.string(), from.next_window, from.time);
    session->attach(std::move(file), std::move(from), request.progress);
  } else {
    session.emplace(scene::load_scene(request.scene));
    const auto& scene = session->scene();
    auto read = read_sections(scene, session->plan());
    if (!read) return 2;
    work = std::move(*read);
    path = request.output.empty() ? fs::path(scene.output.file) : request.output;
    if (path.has_parent_path()) fs::create_directories(path.parent_path());
    session->attach(output::RunFile::create(path, output::RunInfo::of_this_build(scene.text, scene.file.string()),
                                            scene.body_names(), session->participant_names()),
                    std::nullopt, request.progress);
  }

  const auto resume_hint = [&] {
    const auto from = session->checkpointed();
    if (from)
      return fmt::format(
          "the run file {} keeps {} committed windows; continue from its checkpoint at "
          "window {} with: cosim run --resume {}",
          path.string(), session->committed(), *from, path.string());
    if (session->committed() == 0)
      return fmt::format(
          "no window was committed, so there is nothing to resume: fix the cause and run the "
          "scene again ({} records the error)",
          path.string());
    return fmt::format("the run file {} keeps {} committed windows but no checkpoint to resume from", path.string(),
                       session->committed());
  };
  try {
    session->execute();
  } catch (const Interrupted&) {
    session->file().set_status("interrupted", wall());
    spdlog::warn("interrupted; {}", resume_hint());
    return 130;
  } catch (const std::exception& e) {
    session->file().set_status(std::string("failed: ") + e.what(), wall());
    spdlog::error("{}", e.what());
    spdlog::error("{}", resume_hint());
    return 1;
  }
  session->file().set_peak_bytes(session->totals().peak_bytes);
  session->file().set_status("finished", wall());
  if (!request.resume) learn(session->scene(), work, session->totals(), wall(), path);
  spdlog::info("finished in {:.2f} s; wrote {}", wall(), path.string());
  return 0;
}

}  // namespace cosim::run
