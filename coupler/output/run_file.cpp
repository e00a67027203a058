#include "output/run_file.hpp"

#include <chrono>
#include <ctime>
#include <optional>
#include <set>
#include <stdexcept>
#include <utility>

#include "output/checkpoint_group.hpp"
#include "output/h5_groups.hpp"
#include "output/h5_handle.hpp"
#include "output/h5_values.hpp"
#include "output/run_series.hpp"

namespace cosim::output {
namespace {

std::string utc_now_iso8601() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

// Runs f with HDF5's stack printing off and puts the file name on ObjectErrors, so every
// message names both the file and the object.
template <class F>
auto in_file(const std::filesystem::path& path, F&& f) {
  QuietErrors quiet;
  try {
    return f();
  } catch (const ObjectError& e) {
    throw std::runtime_error(path.string() + ": " + e.what());
  }
}

// Names become HDF5 group names: "a/b" would nest and "." means the parent itself.
void check_names(const std::vector<std::string>& names, const char* kind) {
  std::set<std::string> seen;
  for (const std::string& name : names) {
    if (name.empty() || name == "." || name.find('/') != std::string::npos) {
      throw ObjectError(std::string(kind) + " name '" + name + "' cannot name an HDF5 group");
    }
    if (!seen.insert(name).second) {
      throw ObjectError(std::string(kind) + " name '" + name + "' appears twice");
    }
  }
}

void write_status(hid_t file, const std::string& status, double wall_seconds) {
  Handle run = open_group(file, "run");
  write_attribute(run.get(), "status", status);
  write_attribute(run.get(), "wall_seconds", wall_seconds);
}

}  // namespace

struct RunFile::Impl {
  std::filesystem::path path;
  Handle file;
  RunInfo info;
  std::vector<std::string> bodies;
  std::vector<std::string> participants;
  std::optional<Checkpoint> checkpoint;
  std::optional<RunSeries> series;

  // Closes the series before the file, with errors quiet: a destructor cannot report them.
  ~Impl() {
    QuietErrors quiet;
    series.reset();
    file = Handle();
  }
};

RunFile::RunFile(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
RunFile::RunFile(RunFile&&) noexcept = default;
RunFile& RunFile::operator=(RunFile&&) noexcept = default;
RunFile::~RunFile() = default;

RunFile RunFile::create(const std::filesystem::path& path, const RunInfo& info,
                        const std::vector<std::string>& bodies,
                        const std::vector<std::string>& participants) {
  return in_file(path, [&] {
    check_names(bodies, "body");
    check_names(participants, "participant");
    auto impl = std::make_unique<Impl>();
    impl->path = path;
    impl->info = info;
    impl->bodies = bodies;
    impl->participants = participants;
    impl->file = Handle(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT),
                        H5Fclose, "create file");
    const hid_t file = impl->file.get();
    {
      Handle run = create_group(file, "run");
      write_text(run.get(), "scene_text", info.scene_text);
      write_attribute(run.get(), "scene_file", info.scene_file);
      write_attribute(run.get(), "git_hash", info.git_hash);
      write_attribute(run.get(), "cosim_version", info.cosim_version);
      write_attribute(run.get(), "protocol_version", info.protocol_version);
      write_attribute(run.get(), "started", utc_now_iso8601());
      write_attribute(run.get(), "body_names", bodies);
      write_attribute(run.get(), "participant_names", participants);
    }
    write_status(file, "running", 0.0);
    impl->series = RunSeries::create(file, bodies, participants);
    flush(file);
    return RunFile(std::move(impl));
  });
}

RunFile RunFile::resume(const std::filesystem::path& path) {
  return in_file(path, [&] {
    auto impl = std::make_unique<Impl>();
    impl->path = path;
    impl->file = Handle(H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), H5Fclose, "open file");
    const hid_t file = impl->file.get();
    double wall_seconds = 0.0;
    {
      Handle run = open_group(file, "run");
      impl->info.scene_text = read_text(run.get(), "scene_text");
      impl->info.scene_file = read_attribute<std::string>(run.get(), "scene_file");
      impl->info.git_hash = read_attribute<std::string>(run.get(), "git_hash");
      impl->info.cosim_version = read_attribute<std::string>(run.get(), "cosim_version");
      impl->info.protocol_version = read_attribute<int>(run.get(), "protocol_version");
      impl->bodies = read_attribute<std::vector<std::string>>(run.get(), "body_names");
      impl->participants = read_attribute<std::vector<std::string>>(run.get(), "participant_names");
      wall_seconds = read_attribute<double>(run.get(), "wall_seconds");
    }
    impl->checkpoint = read_checkpoint(file, impl->participants);
    if (!impl->checkpoint) {
      throw std::runtime_error("no checkpoint in " + path.string() + ": it cannot be resumed");
    }
    impl->series = RunSeries::open(file, impl->bodies, impl->participants);
    impl->series->cut_after(impl->checkpoint->time);
    write_status(file, "running", wall_seconds);
    flush(file);
    return RunFile(std::move(impl));
  });
}

const RunInfo& RunFile::info() const { return impl_->info; }

const Checkpoint& RunFile::checkpoint() const {
  if (!impl_->checkpoint) throw std::runtime_error(impl_->path.string() + ": no checkpoint yet");
  return *impl_->checkpoint;
}

void RunFile::append(const WindowRecord& w) {
  in_file(impl_->path, [&] {
    impl_->series->append(w);
    flush(impl_->file.get());
  });
}

void RunFile::write_checkpoint(const Checkpoint& c) {
  in_file(impl_->path, [&] {
    output::write_checkpoint(impl_->file.get(), c, impl_->bodies.size(), impl_->participants);
    impl_->checkpoint = c;
  });
}

void RunFile::set_status(const std::string& status, double wall_seconds) {
  in_file(impl_->path, [&] {
    write_status(impl_->file.get(), status, wall_seconds);
    flush(impl_->file.get());
  });
}

}  // namespace cosim::output
