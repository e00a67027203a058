// The run's HDF5 file: what a run leaves behind, and what --resume starts from.
//
// Layout (every series is a chunked, extendible dataset; one row per written window):
//   /run                 attrs: scene_file, git_hash, cosim_version, protocol_version (of
//                        the build that created the file), started (ISO 8601 UTC),
//                        wall_seconds (summed over all sessions of the run), status
//                        ("running", "finished", "failed: ...", "interrupted"), body_names,
//                        participant_names (string lists, scene order); datasets
//                        scene_text (scalar string: a scene can exceed the 64 KiB attribute
//                        limit), resumed_by (n strings: the git hash of the build of each
//                        resume, in order; a dataset because it only grows, see below)
//   /bodies/<name>/      time (n), position (n x 3), orientation (n x 4, w x y z),
//                        velocity (n x 3), angular_velocity (n x 3), force (n x 3),
//                        torque (n x 3)
//   /coupling/           window (n, uint64), time (n), iterations (n, int32), residual (n),
//                        wall_seconds (n): the whole window
//   /coupling/participants/<name>/  wall_seconds (n), substeps (n), field_bytes (n: the
//                        payload bytes of the grid fields the coupler forwarded to it in
//                        the window, over all iterations; 0 for a participant that needs
//                        none); NaN where a window's record had no value for that
//                        participant; attr peak_bytes once a session finished (the largest
//                        peak resident set of its processes, one rank's, over the sessions)
//   /fields/<participant>/grid/  written with the first fields (coupler/field), either
//                        rectilinear: x, y, z, node coordinates per axis (so stretched
//                        axes are exact); or polyhedral: vertices (v x 3), topology
//                        (int64, XDMF Mixed of Polyhedron cells), attr cells (uint64)
//   /fields/<participant>/<window>/  attr time; one dataset per cell-centred field,
//                        (nz, ny, nx) for a scalar, (nz, ny, nx, c) for c components (x
//                        fastest) on a rectilinear grid, (cells) and (cells, c) on a
//                        polyhedral one; <window> is the window index zero-padded to 6
//                        digits. cosim-fluid writes velocity (3), pressure and alpha on its
//                        rectilinear grid; cosim-tracker count, mean_count, density,
//                        velocity (3), temperature and pressure on its polyhedra
//   /fields/<participant>/<window>/points/<set>  (n x 3) the x, y, z of each of the
//                        frame's point sets (coupler/field), e.g. an immersed body's
//                        surface markers or the tracker's particles; (0 x 3) for a set
//                        without points; no group for a frame without sets
//   /fields/<participant>/<window>/point_attributes/<set>/<attribute>  (n) for one
//                        component, (n x c) for c: a value per point of the set, in the
//                        order of points/<set> (float64, or int64 for whole numbers such as
//                        cell indices); a group only for sets that have attributes, none for
//                        a frame without
//   /checkpoint/         attr current ("a" or "b", fixed-length ASCII): the slot holding the
//                        checkpoint; absent until the first checkpoint is complete
//   /checkpoint/{a,b}/   attrs window (last committed window index + 1 = next window),
//                        time; datasets poses (b x 13), forces (b x 6), responses
//                        (b x 78, or 0 rows: the forces' response tensors), and
//                        participants/<name>/state (opaque float64 array), one group per
//                        participant with attr present (int; 0: no state in this checkpoint).
//                        Each of these datasets holds its value in its first `length` rows
//                        (uint64 attr); rows after that are space kept from a longer value.
// Strings are variable-length UTF-8, but for /checkpoint's current. The file is written
// through a journaling driver (journal_driver.hpp): each flush is one commit, and a kill at
// any instant leaves the file as the last finished flush left it, or the next open finishes
// the flush it cut off. After every committed window the file is flushed, so a crash (even
// SIGKILL) after append() returns loses nothing committed. An error inside append() (a full
// disk) can leave some series one row longer than others: resume() cuts them back and
// readers should use the shortest length. A checkpoint is written into the slot `current`
// does not name, flushed, and only then committed by overwriting `current` in place and
// flushing again: an error at any point leaves the previous checkpoint whole. Checkpoint
// writes never free file space (datasets are only overwritten and grown), and resume()
// appends to the resumed_by dataset rather than rewrite a growing attribute, which would
// move /run's object header: the file keeps its layout. create() writes the file whole under <file>.tmp and renames
// it, so a kill before it returns leaves no file rather than part of one.
// Fields come with a sidecar <file>.xmf (XDMF 3: one temporal collection of 3DRectMesh or
// Mixed grids per participant, referencing the datasets by the run file's name; with point
// sets, each step a spatial collection of that grid and a Polyvertex grid per set with its
// attributes node-centred, xdmf.hpp)
// that ParaView opens (with its "XDMF Reader (Xdmf3ReaderS)" once a grid is polyhedral); it
// is rewritten, by rename, after every field write once the file is flushed.
// The file's descriptors are close-on-exec (journal_driver.hpp).
// Errors are std::runtime_error naming the file and the HDF5 object.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "coupler/field/field_frame.hpp"

namespace cosim::output {

struct RunInfo {
  std::string scene_text;
  std::string scene_file;
  std::string git_hash;
  std::string cosim_version;
  int protocol_version = 0;

  // A scene run by this build: its commit, version and protocol (run_info.cpp).
  static RunInfo of_this_build(std::string scene_text, std::string scene_file);
};

// What peek() finds in a run file.
struct RunSummary {
  RunInfo info;                           // as the run was created
  std::vector<std::string> bodies;        // scene order
  std::vector<std::string> participants;  // scene order
  std::string status;                     // as the last session left it
  double wall_seconds = 0.0;              // summed over the sessions that set a status
  std::vector<std::string> resumed_by;    // git hashes, one per resume
  bool has_checkpoint = false;            // false: resume() would throw
  std::uint64_t checkpoint_window = 0;    // with a checkpoint: the window a resume runs next
};

// One committed window, as the coupler writes it.
struct WindowRecord {
  std::uint64_t window = 0;
  double time = 0.0;  // end of the window
  int iterations = 0;
  double residual = 0.0;
  double wall_seconds = 0.0;
  std::vector<double> poses;   // bodies x 13, row-major (scene body order)
  std::vector<double> forces;  // bodies x 6
  std::map<std::string, double> participant_wall_seconds;
  std::map<std::string, double> participant_substeps;
  std::map<std::string, double> participant_field_bytes;
};

struct Checkpoint {
  std::uint64_t next_window = 0;                      // the window to run next
  double time = 0.0;                                  // its start time
  std::vector<double> poses;                          // bodies x 13 at `time`
  std::vector<double> forces;                         // bodies x 6 at `time`
  std::map<std::string, std::vector<double>> states;  // participant -> opaque state
  std::vector<double> responses;                      // bodies x 78 with those forces, or none
};

class RunFile {
 public:
  // Creates (truncates) path and writes /run.
  static RunFile create(const std::filesystem::path& path, const RunInfo& info, const std::vector<std::string>& bodies,
                        const std::vector<std::string>& participants);
  // Reads /run and the checkpoint's window without changing the file (opened read-only),
  // so that --resume can validate what it found before resume() writes anything. Throws
  // naming the file if it is not a run file (or HDF5 cannot open or lock it).
  static RunSummary peek(const std::filesystem::path& path);
  // Opens an existing run file for --resume: reads /run and /checkpoint, cuts every series
  // back to the checkpoint time so the resumed run appends exactly after it, sets status
  // "running" and appends git_hash (the resuming build's) to resumed_by. Field steps after
  // the checkpoint's window are unlinked too and the sidecar rewritten without them.
  static RunFile resume(const std::filesystem::path& path, const std::string& git_hash);
  // Finishes in the file a commit a kill cut off (what <file>.journal holds,
  // journal_driver.hpp) and removes the journal, so that readers without the journal driver
  // (h5py, ParaView) see the file whole; changes nothing else. Returns whether there was
  // such a commit. Throws as peek() does.
  static bool finish_commit(const std::filesystem::path& path);

  RunFile(RunFile&&) noexcept;
  RunFile& operator=(RunFile&&) noexcept;
  ~RunFile();  // closes; the file is always readable afterwards

  const RunInfo& info() const;
  const Checkpoint& checkpoint() const;  // resume(): what was read; throws if none

  void append(const WindowRecord& w);  // writes one row everywhere and flushes
  // Writes the frame as window `window`'s fields of `participant` at `time`, flushes and
  // rewrites the sidecar.
  void write_fields(const std::string& participant, std::uint64_t window, double time, const field::FieldFrame& frame);
  // Replaces the checkpoint: writes the other slot, flushes, switches `current`, flushes.
  void write_checkpoint(const Checkpoint& c);
  // wall_seconds: this session's; the file stores it added to the earlier sessions' total.
  void set_status(const std::string& status, double wall_seconds);
  // Each participant's peak resident set in bytes (its largest process), kept as the larger
  // of this session's and what the file holds from earlier ones.
  void set_peak_bytes(const std::map<std::string, double>& peak_bytes);

 private:
  struct Impl;
  explicit RunFile(std::unique_ptr<Impl>);
  std::unique_ptr<Impl> impl_;
};

}  // namespace cosim::output
