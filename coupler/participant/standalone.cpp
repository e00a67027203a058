#include "coupler/participant/standalone.hpp"

#include <chrono>

#include "coupler/output/run_file.hpp"
#include "coupler/participant/progress.hpp"
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

// The coupler's run file (output::RunFile), as run_standalone() says.
class RunFileRecorder final : public Recorder {
 public:
  RunFileRecorder(const std::filesystem::path& path, const scene::Scene& scene, const Solver& solver,
                  const std::string& name)
      : scene_(scene),
        solver_(solver),
        name_(name),
        file_(output::RunFile::create(path, output::RunInfo::of_this_build(scene.text, scene.file.string()),
                                      scene.body_names(), {name})) {}

  void record(std::uint64_t done, double time, const Outputs& out, double seconds) override {
    const std::uint64_t n = scene_.windows();
    const std::size_t bodies = scene_.bodies.size();
    if (scene_.output.row_at(done, n))
      file_.append({.window = done,
                    .time = time,
                    .iterations = done > 0 ? 1 : 0,
                    .residual = 0.0,
                    .wall_seconds = seconds,
                    .poses = or_zeros(out.poses, protocol::kPoseWidth * bodies),
                    .forces = or_zeros(out.forces, protocol::kForceWidth * bodies),
                    .participant_wall_seconds = {{name_, seconds}},
                    .participant_substeps = {{name_, out.substeps}},
                    .participant_field_bytes = {{name_, 0.0}}});  // nobody forwards fields to a program alone
    if (!scene_.output.fields_at(done, n)) return;
    if (const field::FieldFrame fields = solver_.fields(); !fields.fields.empty())
      file_.write_fields(name_, done, time, fields);
  }

  void set_status(const std::string& status, double seconds) override { file_.set_status(status, seconds); }

 private:
  const scene::Scene& scene_;
  const Solver& solver_;
  std::string name_;
  output::RunFile file_;
};

}  // namespace

void run_standalone(const scene::Scene& scene, Solver& solver, const std::string& name, std::filesystem::path output,
                    const MakeRecorder& make) {
  const auto started = clock::now();
  const Outputs initial = solver.initialise(scene, name, {}, {});

  if (output.empty()) output = scene.output.file;
  if (output.has_parent_path()) std::filesystem::create_directories(output.parent_path());
  const std::unique_ptr<Recorder> recorder =
      make ? make(output) : std::make_unique<RunFileRecorder>(output, scene, solver, name);
  const std::uint64_t n = scene.windows();
  // Shown only on a terminal, and no rank's stderr is one under mpirun.
  Progress progress(n, scene.time.end);
  try {
    recorder->record(0, 0.0, initial, 0.0);
    for (std::uint64_t k = 0; k < n; ++k) {
      const auto window_started = clock::now();
      // Window bounds computed as the coupler does, so both runs take identical steps.
      const Window w{k, 1, static_cast<double>(k) * scene.coupling.window,
                     static_cast<double>(k + 1) * scene.coupling.window};
      const Outputs out = solver.advance(w, {});
      recorder->record(k + 1, w.t1, out, seconds_since(window_started));
      progress.update(k + 1, w.t1, recorder->progress());
    }
  } catch (const std::exception& e) {
    progress.finish();
    recorder->set_status(std::string("failed: ") + e.what(), seconds_since(started));
    throw;
  }
  progress.finish();
  recorder->set_status("finished", seconds_since(started));
}

}  // namespace cosim::participant
