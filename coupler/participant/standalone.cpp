#include "coupler/participant/standalone.hpp"

#include <chrono>

#include "cosim_git_hash.hpp"
#include "coupler/output/run_file.hpp"
#include "coupler/participant/seconds_since.hpp"
#include "coupler/protocol/message.hpp"

namespace cosim::participant {
namespace {

using clock = std::chrono::steady_clock;

// The run file's row of values: the rows', or zeros where the solver gives none.
template <class Row>
std::vector<double> or_zeros(const std::vector<Row>& rows, std::size_t size) {
  return rows.empty() ? std::vector<double>(size, 0.0) : values_of(rows);
}

}  // namespace

void run_standalone(const scene::Scene& scene, Solver& solver, const std::string& name,
                    std::filesystem::path output) {
  const auto started = clock::now();
  const Outputs initial = solver.initialise(scene, name, {}, {});

  if (output.empty()) output = scene.output.file;
  if (output.has_parent_path()) std::filesystem::create_directories(output.parent_path());
  std::vector<std::string> bodies;
  for (const auto& b : scene.bodies) bodies.push_back(b.name);
  auto file = output::RunFile::create(
      output, {scene.text, scene.file.string(), COSIM_GIT_HASH, COSIM_VERSION, protocol::kVersion}, bodies, {name});
  const auto record = [&](std::uint64_t window, double time, const Outputs& out, int iterations, double wall) {
    file.append({.window = window,
                 .time = time,
                 .iterations = iterations,
                 .residual = 0.0,
                 .wall_seconds = wall,
                 .poses = or_zeros(out.poses, protocol::kPoseWidth * bodies.size()),
                 .forces = or_zeros(out.forces, protocol::kForceWidth * bodies.size()),
                 .participant_wall_seconds = {{name, wall}},
                 .participant_substeps = {{name, out.substeps}},
                 .participant_field_bytes = {{name, 0.0}}});  // nobody forwards fields to a program alone
  };
  const std::uint64_t n = scene.windows();
  const auto write_fields = [&](std::uint64_t done, double time) {
    if (!scene.output.fields_at(done, n)) return;
    if (const field::FieldFrame fields = solver.fields(); !fields.fields.empty())
      file.write_fields(name, done, time, fields);
  };

  try {
    record(0, 0.0, initial, 0, 0.0);
    write_fields(0, 0.0);
    for (std::uint64_t k = 0; k < n; ++k) {
      const auto window_started = clock::now();
      // Window bounds computed as the coupler does, so both runs take identical steps.
      const Window w{k, 1, static_cast<double>(k) * scene.coupling.window,
                     static_cast<double>(k + 1) * scene.coupling.window};
      const Outputs out = solver.advance(w, {});
      if (scene.output.row_at(k + 1, n))
        record(k + 1, w.t1, out, 1, seconds_since(window_started));
      write_fields(k + 1, w.t1);
    }
  } catch (const std::exception& e) {
    file.set_status(std::string("failed: ") + e.what(), seconds_since(started));
    throw;
  }
  file.set_status("finished", seconds_since(started));
}

}  // namespace cosim::participant
