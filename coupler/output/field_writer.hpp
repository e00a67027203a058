// Grid fields into the run file, /fields/<participant>/..., with the XDMF sidecar kept up to
// date so ParaView opens the run at any point, a partial one too. Used by RunFile.
#pragma once

#include <hdf5.h>

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>

#include "coupler/field/field_frame.hpp"
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
  // For --resume from window `next_window`: unlinks the steps after it (their point sets
  // and attributes with them), which the resumed run writes again, and takes those up to it
  // into the sidecar.
  void resume(hid_t file, std::uint64_t next_window);
  // Rewrites the sidecar for every step written so far: call it once the file is flushed,
  // so it never names a dataset that is not on disk.
  void write_sidecar() const;

 private:
  std::filesystem::path h5_path_;
  std::map<std::string, XdmfSeries> series_;  // by participant
};

}  // namespace cosim::output
