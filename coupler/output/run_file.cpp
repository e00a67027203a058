#include "coupler/output/run_file.hpp"

#include <algorithm>
#include <optional>
#include <set>
#include <stdexcept>
#include <utility>

#include "coupler/output/checkpoint_group.hpp"
#include "coupler/output/field_writer.hpp"
#include "coupler/output/h5_groups.hpp"
#include "coupler/output/h5_handle.hpp"
#include "coupler/output/h5_values.hpp"
#include "coupler/output/journal_driver.hpp"
#include "coupler/output/run_series.hpp"
#include "coupler/output/in_file.hpp"
#include "coupler/output/text.hpp"

namespace cosim::output {
namespace {

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

Handle open_run_file(const std::filesystem::path& path, unsigned flags) {
  // Said before H5Fopen would: its message for this is "file signature not found".
  if (H5Fis_hdf5(path.c_str()) == 0) throw ObjectError("not a cosim run file (not HDF5)");
  Handle file(H5Fopen(path.c_str(), flags, journaled_access().get()), H5Fclose, "open file");
  if (!has_link(file.get(), "run")) throw ObjectError("not a cosim run file (no /run group)");
  return file;
}

const char* const kResumedBy = "resumed_by";

RunSummary read_summary(hid_t file) {
  RunSummary s;
  Handle run = open_group(file, "run");
  s.info.scene_text = read_text(run.get(), "scene_text");
  s.info.scene_file = read_attribute<std::string>(run.get(), "scene_file");
  s.info.git_hash = read_attribute<std::string>(run.get(), "git_hash");
  s.info.cosim_version = read_attribute<std::string>(run.get(), "cosim_version");
  s.info.protocol_version = read_attribute<int>(run.get(), "protocol_version");
  s.bodies = read_attribute<std::vector<std::string>>(run.get(), "body_names");
  s.participants = read_attribute<std::vector<std::string>>(run.get(), "participant_names");
  s.status = read_attribute<std::string>(run.get(), "status");
  s.wall_seconds = read_attribute<double>(run.get(), "wall_seconds");
  if (has_link(run.get(), kResumedBy)) s.resumed_by = read_text_list(run.get(), kResumedBy);
  return s;
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
  std::optional<FieldWriter> fields;  // from the first field write, or resume()
  double earlier_wall_seconds = 0.0;  // of the sessions before this one

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

RunFile RunFile::create(const std::filesystem::path& path, const RunInfo& info, const std::vector<std::string>& bodies,
                        const std::vector<std::string>& participants) {
  return in_file(path, [&] {
    check_names(bodies, "body");
    check_names(participants, "participant");
    auto impl = std::make_unique<Impl>();
    impl->path = path;
    impl->info = info;
    impl->bodies = bodies;
    impl->participants = participants;
    // Written whole under another name and renamed: a kill before the file is complete
    // leaves no file at `path` rather than half of one.
    std::filesystem::path partial = path;
    partial += ".tmp";
    {
      const Handle file(H5Fcreate(partial.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, journaled_access().get()), H5Fclose,
                        "create file");
      {
        Handle run = create_group_for_large_attributes(file.get(), "run");
        write_text(run.get(), "scene_text", info.scene_text);
        write_attribute(run.get(), "scene_file", info.scene_file);
        write_attribute(run.get(), "git_hash", info.git_hash);
        write_attribute(run.get(), "cosim_version", info.cosim_version);
        write_attribute(run.get(), "protocol_version", info.protocol_version);
        write_attribute(run.get(), "started", utc_now_iso8601());
        write_attribute(run.get(), "body_names", bodies);
        write_attribute(run.get(), "participant_names", participants);
        create_text_list(run.get(), kResumedBy);
      }
      write_status(file.get(), "running", 0.0);
      RunSeries::create(file.get(), bodies, participants);
    }
    // A journal left by an earlier file of this name belongs to that file.
    std::filesystem::remove(journal_of(path));
    std::filesystem::rename(partial, path);
    impl->file = open_run_file(path, H5F_ACC_RDWR);
    impl->series = RunSeries::open(impl->file.get(), bodies, participants);
    return RunFile(std::move(impl));
  });
}

RunSummary RunFile::peek(const std::filesystem::path& path) {
  return in_file(path, [&] {
    const Handle file = open_run_file(path, H5F_ACC_RDONLY);
    RunSummary s = read_summary(file.get());
    const std::optional<Checkpoint> c = read_checkpoint(file.get(), s.participants);
    s.has_checkpoint = c.has_value();
    if (c) s.checkpoint_window = c->next_window;
    return s;
  });
}

bool RunFile::finish_commit(const std::filesystem::path& path) {
  const bool pending = commit_pending(path);
  // Opening for writing finishes the commit in the file; closing removes the journal.
  in_file(path, [&] { open_run_file(path, H5F_ACC_RDWR); });
  return pending;
}

RunFile RunFile::resume(const std::filesystem::path& path, const std::string& git_hash) {
  return in_file(path, [&] {
    auto impl = std::make_unique<Impl>();
    impl->path = path;
    impl->file = open_run_file(path, H5F_ACC_RDWR);
    const hid_t file = impl->file.get();
    RunSummary s = read_summary(file);
    impl->info = s.info;
    impl->bodies = s.bodies;
    impl->participants = s.participants;
    impl->earlier_wall_seconds = s.wall_seconds;
    impl->checkpoint = read_checkpoint(file, impl->participants);
    if (!impl->checkpoint) {
      throw std::runtime_error("no checkpoint in " + path.string() + ": it cannot be resumed");
    }
    impl->series = RunSeries::open(file, impl->bodies, impl->participants);
    impl->series->cut_after(impl->checkpoint->time);
    impl->fields.emplace(path);
    impl->fields->resume(file, impl->checkpoint->next_window);
    write_status(file, "running", s.wall_seconds);
    {
      Handle run = open_group(file, "run");
      if (!has_link(run.get(), kResumedBy)) create_text_list(run.get(), kResumedBy);  // older file
      append_text(run.get(), kResumedBy, git_hash);
    }
    flush(file);
    impl->fields->write_sidecar();
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

void RunFile::write_fields(const std::string& participant, std::uint64_t window, double time,
                           const field::FieldFrame& frame) {
  in_file(impl_->path, [&] {
    if (!impl_->fields) impl_->fields.emplace(impl_->path);
    impl_->fields->write(impl_->file.get(), participant, window, time, frame);
    flush(impl_->file.get());
    impl_->fields->write_sidecar();
  });
}

void RunFile::write_checkpoint(const Checkpoint& c) {
  in_file(impl_->path, [&] {
    output::write_checkpoint(impl_->file.get(), c, impl_->bodies.size(), impl_->participants);
    impl_->checkpoint = c;
  });
}

void RunFile::set_peak_bytes(const std::map<std::string, double>& peak_bytes) {
  in_file(impl_->path, [&] {
    const Handle participants = open_group(impl_->file.get(), "coupling/participants");
    for (const auto& [name, bytes] : peak_bytes) {
      if (!has_link(participants.get(), name)) continue;
      const Handle group = open_group(participants.get(), name);
      const double earlier =
          has_attribute(group.get(), "peak_bytes") ? read_attribute<double>(group.get(), "peak_bytes") : 0.0;
      write_attribute(group.get(), "peak_bytes", std::max(earlier, bytes));
    }
    flush(impl_->file.get());
  });
}

void RunFile::set_status(const std::string& status, double wall_seconds) {
  in_file(impl_->path, [&] {
    write_status(impl_->file.get(), status, impl_->earlier_wall_seconds + wall_seconds);
    flush(impl_->file.get());
  });
}

}  // namespace cosim::output
