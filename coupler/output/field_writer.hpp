// Grid fields into the run file, /fields/<participant>/..., with the XDMF sidecar kept up to
// date so ParaView opens the run at any point, a partial one too. Used by RunFile.
#pragma once

#include <hdf5.h>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <utility>

#include "coupler/field/field_frame.hpp"
#include "coupler/output/h5_handle.hpp"
#include "coupler/output/xdmf.hpp"

namespace cosim::output {

class FieldWriter {
 public:
  // h5_path: the run file, whose sidecar is h5_path with extension .xmf.
  explicit FieldWriter(std::filesystem::path h5_path);

  // Writes the grid (first call per participant: /fields/<participant>/grid, layout in
  // run_file.hpp) and the step group /fields/<participant>/<window, 6+ digits>/<field> with
  // attr time, points/<set> for each point set and point_attributes/<set>/<attribute> for
  // each of its attributes. Throws ObjectError for a frame whose sizes do not add up
  // (field::grid_problem()), whose point sets are not (field::point_sets_problem()), that
  // has point sets beside a cell field named "points" (attributes beside one named
  // "point_attributes"), or whose grid is not the first one's kind and size.
  void write(hid_t file, const std::string& participant, std::uint64_t window, double time,
             const field::FieldFrame& frame);
  // The same step with its cell fields in blocks, so that the writer holds one block at a
  // time (a box spread over MPI ranks, received rank by rank): `frame` names the fields
  // and their components (their values are left empty) on a rectilinear grid, and
  // `blocks(take)` calls take() with each block in turn. Throws ObjectError as write()
  // does, and for a polyhedral grid, a block that does not lie within the grid or does not
  // hold the frame's fields with its cells' values, or blocks whose cells do not add up to
  // the grid's.
  using BlockSink = std::function<void(const field::CellBlock&)>;
  void write(hid_t file, const std::string& participant, std::uint64_t window, double time,
             const field::FieldFrame& frame, const std::function<void(const BlockSink&)>& blocks);
  // For --resume from window `next_window`: unlinks the steps after it (their point sets
  // and attributes with them), which the resumed run writes again, and takes those up to it
  // into the sidecar.
  void resume(hid_t file, std::uint64_t next_window);
  // Rewrites the sidecar for every step written so far: call it once the file is flushed,
  // so it never names a dataset that is not on disk.
  void write_sidecar() const;

 private:
  // The step's group, with its attribute time, on the participant's grid (written with the
  // first step), and its entry in the participant's series.
  std::pair<Handle, XdmfStep> open_step(hid_t file, const std::string& participant, std::uint64_t window, double time,
                                        const field::FieldFrame& frame);

  std::filesystem::path h5_path_;
  std::map<std::string, XdmfSeries> series_;  // by participant
};

}  // namespace cosim::output
