#include "coupler/estimate/estimate.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "coupler/estimate/run_record.hpp"

namespace cosim::estimate {
namespace {

// Priors: the cost models before any run was measured on this host, rounded from
// `cosim calibrate` on the 2-core development machine (bench/estimate/README.md). Their
// weight in a fit is small, so the first measured runs here replace them.
Coefficients prior(const std::string& program) {
  if (program == "fluid")
    return {2.3e-4, {{"cells", 7.6e-7}, {"markers", 1.1e-5}}, 55e6, {{"cells", 670}, {"markers", 6.6e3}}};
  if (program == "rigidbody") return {1.5e-6, {{"bodies", 6e-7}}, 18e6, {{"bodies", 1.15e5}}};
  if (program == "tracker")
    return {0,
            {{"particles", 0},
             {"crossings", 1.1e-7},
             {"cells", 2.1e-7},
             {"primitive_tests", 2e-7},
             {"colliding_particles", 1e-7}},
            65e6,
            {{"particles", 245}, {"cells", 1.3e3}}};
  if (program == kCoupler)
    return {0,
            {{"exchanges", 0},
             {"body_rows", 1.2e-4},
             {"field_bytes", 3.5e-8},
             {"start:fluid", 1.2},
             {"start:rigidbody", 0},
             {"start:tracker", 1.0}},
            0,
            {}};
  return {};  // an external program: only what it measured
}

bool empty(const Coefficients& c) {
  const auto zero = [](const Units& u) {
    return std::all_of(u.begin(), u.end(), [](const auto& e) { return e.second == 0; });
  };
  return c.seconds_per_step == 0 && zero(c.seconds_per_unit) && c.base_bytes == 0 && zero(c.bytes_per_unit);
}

// Steps per window and iteration: as this scene's last run took them, or the window over the
// program's mean step where it chooses its own (its work's dt, the window's shortened steps
// counted), or the window over its fixed step rounded up to whole steps.
double steps_per_exchange(const scene::Scene& scene, const scene::Participant& p, const ProgramWork* work,
                          const RunRecord* last) {
  if (last != nullptr && last->programs.contains(p.name) && last->iterations > 0 && last->programs.at(p.name).steps > 0)
    return last->programs.at(p.name).steps / last->iterations;
  if (work != nullptr && work->dt > 0 && (!(p.dt > 0) || work->dt < p.dt))
    return std::max(1.0, scene.coupling.window / work->dt);
  if (!(p.dt > 0)) return 1;
  return std::max(1.0, std::ceil(scene.coupling.window / p.dt - 1e-9));
}

// How much slower (> 1) or faster this scene's last run took than the model said.
double measured_ratio(const RunRecord* last, const std::string& program, const Coefficients& model) {
  if (last == nullptr) return 1;
  const auto it = last->programs.find(program);
  if (it == last->programs.end() || !(it->second.steps > 0) || !(it->second.seconds > 0)) return 1;
  const double modelled = step_seconds(model, it->second.per_step);
  return modelled > 0 ? it->second.seconds / it->second.steps / modelled : 1;
}

// Rows a series gets over `windows` windows when written every `every`: the start, every
// N-th window and the last.
double written(double windows, int every) {
  return every > 0 ? std::floor(windows / every) + 1 + (std::fmod(windows, every) > 0 ? 1 : 0) : 0.0;
}

double frame_bytes(const std::vector<scene::Participant>& start, const std::map<std::string, ProgramWork>& work) {
  double frame = 0;
  for (const auto& p : start)
    if (scene::has(p.provides, scene::Data::Fields) && work.contains(p.name)) frame += work.at(p.name).frame_bytes;
  return frame;
}

std::string duration(double s) {
  if (s < 10) return fmt::format("{:.1f} s", s);
  if (s < 90) return fmt::format("{:.0f} s", s);
  if (s < 5400) return fmt::format("{:.1f} min", s / 60);
  return fmt::format("{:.1f} h", s / 3600);
}

std::string bytes(double b) {
  if (b < 1e6) return fmt::format("{:.0f} kB", std::max(1.0, b / 1e3));
  if (b < 1e9) return fmt::format("{:.0f} MB", b / 1e6);
  return fmt::format("{:.1f} GB", b / 1e9);
}

std::string count(double n) {
  if (n < 1e4) return fmt::format("{:.0f}", n);
  if (n < 1e6) return fmt::format("{:.0f} k", n / 1e3);
  if (n < 1e9) return fmt::format("{:.3g} M", n / 1e6);
  return fmt::format("{:.3g} G", n / 1e9);
}

}  // namespace

std::string estimate_here(const scene::Scene& scene, const std::vector<scene::Participant>& start,
                          const std::map<std::string, ProgramWork>& work, const std::string& build) {
  try {
    return estimate_line(estimate(scene, start, work, CostStore::load(CostStore::default_path()), build));
  } catch (const std::runtime_error& e) {
    return std::string("estimate: none (") + e.what() + ")";
  }
}

Coefficients model_of(const std::string& program, const CostStore& store, const std::string& build) {
  return fit(store.observations(program, build), prior(program));
}

double run_file_bytes(const scene::Scene& scene, const std::vector<scene::Participant>& start,
                      const std::map<std::string, ProgramWork>& work) {
  const auto windows = static_cast<double>(scene.windows());
  // Series grow by chunks of 256 rows (coupler/output/series.cpp).
  const double rows = 256 * std::ceil(written(windows, scene.output.every) / 256);
  const auto bodies = static_cast<double>(scene.bodies.size());
  // A body's row: time, position, orientation, velocity, angular velocity, force, torque;
  // and its group of seven datasets, about 22 kB of HDF5's own structures (measured on
  // `cosim calibrate`'s 64 and 512 spheres: 22.9 and 21.3 kB).
  const double body_series = bodies * (rows * 20 * 8 + 22e3);
  // The coupling's row: window, time, iterations, residual, wall; per participant its wall
  // seconds, substeps and field bytes.
  const double coupling_series = rows * 8 * (5 + 3 * static_cast<double>(start.size()));
  double states = 0;
  bool responses = false;
  for (const auto& p : start) {
    if (!work.contains(p.name)) continue;
    states += work.at(p.name).state_bytes;
    responses = responses || (p.name == "fluid" && work.at(p.name).held.contains("markers") &&
                              work.at(p.name).held.at("markers") > 0);
  }
  // Two checkpoint slots: poses (13), forces (6) and, from the immersed boundary, response
  // tensors (78) per body, and every program's state.
  const double checkpoints = 2 * (bodies * 8 * (13 + 6 + (responses ? 78 : 0)) + states);
  // HDF5's superblock, groups and attributes and the scene's text: about 50 kB.
  const double fixed = 50e3 + static_cast<double>(scene.text.size());
  return fixed + body_series + coupling_series + checkpoints +
         written(windows, scene.output.fields_every) * frame_bytes(start, work);
}

Units coupler_work(const scene::Scene& scene, const std::vector<scene::Participant>& start,
                   const std::map<std::string, ProgramWork>& work, double exchanges) {
  const auto windows = static_cast<double>(scene.windows());
  Units out{{"exchanges", exchanges},
            {"body_rows", static_cast<double>(scene.bodies.size()) * written(windows, scene.output.every)},
            {"field_bytes", written(windows, scene.output.fields_every) * frame_bytes(start, work)}};
  // Each built-in program's start-up (MPI and PETSc, its mesh, its bodies' markers) until it
  // answers; the built-in ones are those that report their work.
  for (const auto& p : start)
    if (work.contains(p.name)) out["start:" + p.name] = 1;
  return out;
}

Estimate estimate(const scene::Scene& scene, const std::vector<scene::Participant>& start,
                  const std::map<std::string, ProgramWork>& work, const CostStore& store, const std::string& build) {
  Estimate out;
  const RunRecord* last = store.last_run_of(scene_key(scene));
  out.scene_measured = last != nullptr;
  for (const auto& r : store.records()) (r.build == build ? out.runs_measured : out.runs_other_builds) += 1;
  // With nobody on one side of the exchange, an implicit scheme has no loop to close and
  // takes one pass per window (coupler/run/window.cpp).
  const auto provides = [&](scene::Data d) {
    return std::any_of(start.begin(), start.end(),
                       [&](const scene::Participant& p) { return scene::has(p.provides, d); });
  };
  const bool implicit =
      scene::is_implicit(scene.coupling.scheme) && provides(scene::Data::Poses) && provides(scene::Data::Forces);
  const bool serial = scene::is_serial(scene.coupling.scheme);
  out.iterations_per_window = implicit ? kAssumedIterations : 1.0;
  if (implicit && last != nullptr && last->windows > 0) {
    out.iterations_per_window = last->iterations / last->windows;
    out.iterations_measured = true;
  }
  const auto windows = static_cast<double>(scene.windows());
  const double exchanges = windows * out.iterations_per_window;

  double per_exchange_serial = 0, per_exchange_parallel = 0;
  for (const auto& p : start) {
    ProgramEstimate e;
    e.name = p.name;
    const Coefficients model = model_of(p.name, store, build);
    const ProgramWork* w = work.contains(p.name) ? &work.at(p.name) : nullptr;
    const Units none;
    const Units& per_step = w != nullptr ? w->per_step : none;
    const Units& held = w != nullptr ? w->held : none;
    e.modelled = !empty(model);
    e.grows = w != nullptr && w->grows;
    e.steps = exchanges * steps_per_exchange(scene, p, w, last);
    const double step = step_seconds(model, per_step) * measured_ratio(last, p.name, model);
    e.seconds = e.steps * step;
    e.peak_bytes = memory_bytes(model, held);
    double largest = model.seconds_per_step;
    for (const auto& [unit, c] : model.seconds_per_unit)
      if (per_step.contains(unit) && c * per_step.at(unit) > largest) {
        largest = c * per_step.at(unit);
        e.largest_unit = unit;
        e.largest_count = per_step.at(unit);
      }
    const double window_seconds = e.seconds / std::max(exchanges, 1.0);
    per_exchange_serial += window_seconds;
    per_exchange_parallel = std::max(per_exchange_parallel, window_seconds);
    out.programs.push_back(e);
  }
  const Coefficients coupler = model_of(kCoupler, store, build);
  const double overhead =
      step_seconds(coupler, coupler_work(scene, start, work, exchanges)) * measured_ratio(last, kCoupler, coupler);
  out.wall_seconds = exchanges * (serial ? per_exchange_serial : per_exchange_parallel) + overhead;
  out.disk_bytes = run_file_bytes(scene, start, work);
  return out;
}

std::string estimate_line(const Estimate& e) {
  std::string line = "estimate: " + duration(e.wall_seconds) + " here";
  const auto top = std::max_element(e.programs.begin(), e.programs.end(),
                                    [](const auto& a, const auto& b) { return a.seconds < b.seconds; });
  if (top != e.programs.end() && top->seconds > 0 && e.wall_seconds > 0) {
    const double share = 100 * top->seconds / e.wall_seconds;
    line += fmt::format(" ({} {:.0f} %: ", top->name, std::min(share, 100.0));
    line += top->largest_unit.empty()
                ? fmt::format("{} steps)", count(top->steps))
                : fmt::format("{} {} x {} steps)", count(top->largest_count), top->largest_unit, count(top->steps));
  }
  std::string memory, unknown;
  for (const auto& p : e.programs) {
    if (!p.modelled) {
      unknown += (unknown.empty() ? "" : ", ") + p.name;
      continue;
    }
    memory += (memory.empty() ? "" : ", ") + p.name + " " + bytes(p.peak_bytes);
  }
  if (!memory.empty()) line += "; memory " + memory;
  line += "; run file " + bytes(e.disk_bytes);
  if (e.runs_measured > 0)
    line += fmt::format("; fitted to {} run{} of this build here", e.runs_measured, e.runs_measured > 1 ? "s" : "");
  else if (e.runs_other_builds > 0)
    line += fmt::format("; fitted to {} run{} of other builds here (`cosim calibrate` measures this one)",
                        e.runs_other_builds, e.runs_other_builds > 1 ? "s" : "");
  else
    line += "; not measured here yet (`cosim calibrate`)";
  if (e.scene_measured) line += ", this scene's last run";
  if (!e.iterations_measured && e.iterations_per_window > 1)
    line += fmt::format(", {:.0f} iterations per window assumed", e.iterations_per_window);
  if (!unknown.empty()) line += "; " + unknown + " not estimated (nothing measured)";
  for (const auto& p : e.programs)
    if (p.grows && !e.scene_measured) line += "; " + p.name + "'s inflow adds to the counts at the start: more";
  return line;
}

}  // namespace cosim::estimate
