// The standalone tracker's HDF5 file, in the run file's spirit (coupler/output/run_file.hpp)
// with the tracker's grid (output_grid.hpp):
//   /run                      attrs scene_file, git_hash, cosim_version, started, status,
//                             wall_seconds, participant_names ["tracker"]; scene_text
//   /fields/tracker/grid/     the run file's grid (output/run_file.hpp, written by its
//                             FieldWriter; output_grid.hpp): of a box of hexahedra its
//                             nodes x, y, z, the fields then (nz, ny, nx[, c]); of other
//                             meshes vertices (v x 3), topology (int64, XDMF Mixed polyhedra,
//                             see mixed_topology.hpp), attr cells, the fields (cells[, c]);
//                             and volume (m^3, shaped as the fields' cells)
//   /fields/tracker/<step>/   attr time; per cell (cell_fields.hpp): count (particles at
//                             that step), and averaged over the steps since the previous
//                             write (at step 0 the initial state): mean_count, density
//                             (1/m^3), velocity (cells x 3, m/s), temperature (K), pressure
//                             (Pa): the moments of tracking/sampling.hpp. <step>: the step
//                             index, 6+ digits
//   /fields/tracker/<step>/points/particles  with particle_output (scene_particle_output.hpp)
//                             at the steps it names: (n x 3) the particles' positions (all,
//                             or the sample), in cell order; and beside them
//                             point_attributes/particles/ velocity (n x 3, m/s), cell (n,
//                             int64) and per obstacle state_<name> (n x 2, int64: the high
//                             and low 32 bits of its logical state) and inside_<name> (n,
//                             int64, 1 inside it), particle_dump.hpp
//   /tracker/                 one row per written step: step (uint64), time, particles
//                             (uint64), moves (11 columns, attr columns: the MoveTally
//                             totals since the start)
//   /tracker/objects/         attr names; hits, absorbed, entered, left, released (rows x
//                             objects, uint64, totals since the start; released: states
//                             found inside a wall and repaired, 0 in a sound run), impulse and
//                             angular_impulse (rows x 3 objects: x y z per object; momentum and
//                             its moment about the object's pose origin given to the object,
//                             per unit particle mass: m/s, m^2/s), energy (rows x objects:
//                             kinetic energy given to it per unit particle mass, m^2/s^2;
//                             times mass and weight over the time, the heat flow into it, W)
//   /tracker/patches/         attr names (the mesh's boundary patches); area (m^2 per patch);
//                             hits, absorbed (rows x patches, uint64), impulse (rows x 3
//                             patches), energy (rows x patches): as for objects, what the
//                             particles gave each patch's walls since the start. The shear
//                             stress on a patch: impulse x mass x weight / (area x time)
// Object and patch tables are 2-d even for one object or patch, so [:, i] reads column i.
// The sidecar <file>.xmf is rewritten after every write, once the file is flushed; the
// particles are a Polyvertex grid "particles" in it, their attributes node-centred.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "coupler/field/field_frame.hpp"
#include "coupler/scene/scene.hpp"
#include "tracker/program/output_grid.hpp"
#include "tracker/tracking/move.hpp"

namespace cosim::tracker::program {

struct Sample {
  std::uint64_t step = 0;
  double time = 0.0;
  std::uint64_t particles = 0;
  // On the grid the file was made with: the cell fields (cell_fields.hpp) and the point
  // sets, e.g. the particles (particle_dump.hpp), as TrackerSolver::fields() gives them.
  field::FieldFrame fields;
  std::vector<tracking::ObstacleTally> objects;
  std::vector<tracking::SurfaceTally> patches;  // per boundary patch, by Mesh::patches index
  tracking::MoveTally moves;
};

class TrackerFile {
 public:
  // Creates (truncates) path; errors are std::runtime_error naming the file.
  TrackerFile(const std::filesystem::path& path, const scene::Scene& scene, const OutputGrid& grid,
              const std::vector<std::string>& object_names);
  TrackerFile(TrackerFile&&) noexcept;
  ~TrackerFile();

  // Flushes, then rewrites the sidecar. With `blocks` the sample's fields name the cell
  // fields and blocks() hands over their values block by block
  // (output::FieldWriter::write's).
  using Blocks = std::function<void(const std::function<void(const field::CellBlock&)>&)>;
  void write(const Sample& sample, const Blocks& blocks = {});
  void set_status(const std::string& status, double wall_seconds);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cosim::tracker::program
