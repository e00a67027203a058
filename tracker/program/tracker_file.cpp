#include "tracker/program/tracker_file.hpp"

#include <hdf5.h>

#include "cosim_git_hash.hpp"
#include "coupler/output/field_writer.hpp"
#include "coupler/output/h5_groups.hpp"
#include "coupler/output/h5_handle.hpp"
#include "coupler/output/h5_values.hpp"
#include "coupler/output/series.hpp"
#include "coupler/output/in_file.hpp"
#include "coupler/output/text.hpp"
#include "tracker/step/cell_volumes.hpp"

namespace cosim::tracker::program {
namespace {

using output::Handle;
using output::Series;

std::vector<std::string> move_columns() {
  std::vector<std::string> names;
  for (const tracking::MoveCounter& c : tracking::kMoveCounters) names.emplace_back(c.name);
  return names;
}

std::vector<std::uint64_t> columns_of(const tracking::MoveTally& t) {
  std::vector<std::uint64_t> values;
  for (const tracking::MoveCounter& c : tracking::kMoveCounters)
    values.push_back(static_cast<std::uint64_t>(t.*c.count));
  return values;
}

}  // namespace

struct TrackerFile::Impl {
  Impl(const std::filesystem::path& p, const OutputGrid& grid, std::size_t object_count)
      : path(p), objects(object_count), patches(grid.patches.size()), fields(p), volume(grid.volume), box(grid.box) {}

  // Into the grid's group, once the first step has made it: a box's slab by slab, shaped
  // as the fields (nz, ny, nx), so that numpy's density * volume broadcasts.
  void write_volume() {
    Handle grid = output::open_group(file.get(), "/fields/tracker/grid");
    if (!box) {
      output::write_array(grid.get(), "volume", {volume.size()}, volume.data());
      volume = {};
      return;
    }
    std::array<int, 3> n{};
    for (int a = 0; a < 3; ++a) n[a] = static_cast<int>(mesh::axis_nodes(box->axes[a]).size()) - 1;
    const std::vector<hsize_t> dims{hsize_t(n[2]), hsize_t(n[1]), hsize_t(n[0])};
    output::create_array(grid.get(), "volume", dims);
    for (int k = 0; k < n[2]; ++k)
      output::write_block(grid.get(), "volume", {hsize_t(k), 0, 0}, {1, dims[1], dims[2]},
                          step::cell_volumes(*box, {0, 0, k}, {n[0], n[1], k + 1}).data());
    box.reset();
  }

  std::filesystem::path path;
  Handle file;
  std::size_t objects = 0;
  std::vector<Series> rows;     // step, time, particles, moves
  std::vector<Series> tallies;  // hits, absorbed, entered, left, released, impulse, angular_impulse, energy
  std::size_t patches = 0;
  std::vector<Series> patch_tallies;  // hits, absorbed, impulse, energy
  output::FieldWriter fields;
  // Until the first step wrote the grid's group: the volumes for it (OutputGrid's).
  std::vector<double> volume;
  std::optional<mesh::BoxSpec> box;
};

TrackerFile::TrackerFile(const std::filesystem::path& path, const scene::Scene& scene, const OutputGrid& grid,
                         const std::vector<std::string>& object_names)
    : impl_(std::make_unique<Impl>(path, grid, object_names.size())) {
  Impl& m = *impl_;
  output::in_file(path, [&] {
    m.file = Handle(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose, "create file");
    const hid_t file = m.file.get();
    {
      Handle run = output::create_group(file, "run");
      output::write_text(run.get(), "scene_text", scene.text);
      output::write_attribute(run.get(), "scene_file", scene.file.string());
      output::write_attribute(run.get(), "git_hash", std::string(COSIM_GIT_HASH));
      output::write_attribute(run.get(), "cosim_version", std::string(COSIM_VERSION));
      output::write_attribute(run.get(), "started", output::utc_now_iso8601());
      output::write_attribute(run.get(), "participant_names", std::vector<std::string>{"tracker"});
      output::write_attribute(run.get(), "status", std::string("running"));
      output::write_attribute(run.get(), "wall_seconds", 0.0);
    }
    Handle series = output::create_group(file, "tracker");
    m.rows.push_back(Series::create(series.get(), "step", 1, H5T_NATIVE_UINT64));
    m.rows.push_back(Series::create(series.get(), "time", 1, H5T_NATIVE_DOUBLE));
    m.rows.push_back(Series::create(series.get(), "particles", 1, H5T_NATIVE_UINT64));
    m.rows.push_back(Series::create(series.get(), "moves", tracking::kMoveCounters.size(), H5T_NATIVE_UINT64));
    {
      Handle moves(H5Dopen2(series.get(), "moves", H5P_DEFAULT), H5Dclose, "open /tracker/moves");
      output::write_attribute(moves.get(), "columns", move_columns());
    }
    Handle objects = output::create_group(series.get(), "objects");
    output::write_attribute(objects.get(), "names", object_names);
    // A dataset needs at least one column: with no objects the tallies are not written.
    if (m.objects > 0) {
      for (const char* name : {"hits", "absorbed", "entered", "left", "released"})
        m.tallies.push_back(Series::create_table(objects.get(), name, m.objects, H5T_NATIVE_UINT64));
      m.tallies.push_back(Series::create_table(objects.get(), "impulse", 3 * m.objects, H5T_NATIVE_DOUBLE));
      m.tallies.push_back(Series::create_table(objects.get(), "angular_impulse", 3 * m.objects, H5T_NATIVE_DOUBLE));
      m.tallies.push_back(Series::create_table(objects.get(), "energy", m.objects, H5T_NATIVE_DOUBLE));
    }
    Handle patches = output::create_group(series.get(), "patches");
    output::write_attribute(patches.get(), "names", grid.patches);
    if (m.patches > 0) {
      output::write_array(patches.get(), "area", {grid.patch_area.size()}, grid.patch_area.data());
      for (const char* name : {"hits", "absorbed"})
        m.patch_tallies.push_back(Series::create_table(patches.get(), name, m.patches, H5T_NATIVE_UINT64));
      m.patch_tallies.push_back(Series::create_table(patches.get(), "impulse", 3 * m.patches, H5T_NATIVE_DOUBLE));
      m.patch_tallies.push_back(Series::create_table(patches.get(), "energy", m.patches, H5T_NATIVE_DOUBLE));
    }
    output::flush(file);
  });
}

TrackerFile::TrackerFile(TrackerFile&&) noexcept = default;
TrackerFile::~TrackerFile() = default;

void TrackerFile::write(const Sample& s, const Blocks& blocks) {
  Impl& m = *impl_;
  output::in_file(m.path, [&] {
    const hid_t file = m.file.get();
    if (s.objects.size() != m.objects)
      throw output::ObjectError("step " + std::to_string(s.step) + ": " + std::to_string(s.objects.size()) +
                                " object tallies for " + std::to_string(m.objects) + " objects");
    if (blocks)
      m.fields.write(file, "tracker", s.step, s.time, s.fields, blocks);
    else
      m.fields.write(file, "tracker", s.step, s.time, s.fields);
    if (!m.volume.empty() || m.box) m.write_volume();  // the first write has just made the grid's group

    m.rows[0].append(&s.step);
    m.rows[1].append(&s.time);
    m.rows[2].append(&s.particles);
    m.rows[3].append(columns_of(s.moves).data());
    if (m.objects > 0) {
      std::vector<std::vector<std::uint64_t>> counts(5);
      std::vector<double> impulse, angular_impulse, energy;
      for (const tracking::ObstacleTally& t : s.objects) {
        const long long v[] = {t.hits, t.absorbed, t.entered, t.left, t.released};
        for (std::size_t k = 0; k < counts.size(); ++k) counts[k].push_back(static_cast<std::uint64_t>(v[k]));
        impulse.insert(impulse.end(), t.impulse.begin(), t.impulse.end());
        angular_impulse.insert(angular_impulse.end(), t.angular_impulse.begin(), t.angular_impulse.end());
        energy.push_back(t.energy);
      }
      for (std::size_t k = 0; k < counts.size(); ++k) m.tallies[k].append(counts[k].data());
      m.tallies[5].append(impulse.data());
      m.tallies[6].append(angular_impulse.data());
      m.tallies[7].append(energy.data());
    }
    if (s.patches.size() != m.patches)
      throw output::ObjectError("step " + std::to_string(s.step) + ": " + std::to_string(s.patches.size()) +
                                " patch tallies for " + std::to_string(m.patches) + " patches");
    if (m.patches > 0) {
      std::vector<std::uint64_t> hits, absorbed;
      std::vector<double> impulse, energy;
      for (const tracking::SurfaceTally& t : s.patches) {
        hits.push_back(static_cast<std::uint64_t>(t.hits));
        absorbed.push_back(static_cast<std::uint64_t>(t.absorbed));
        impulse.insert(impulse.end(), t.impulse.begin(), t.impulse.end());
        energy.push_back(t.energy);
      }
      m.patch_tallies[0].append(hits.data());
      m.patch_tallies[1].append(absorbed.data());
      m.patch_tallies[2].append(impulse.data());
      m.patch_tallies[3].append(energy.data());
    }
    output::flush(file);
  });
  m.fields.write_sidecar();
}

void TrackerFile::set_status(const std::string& status, double wall_seconds) {
  Impl& m = *impl_;
  output::in_file(m.path, [&] {
    Handle run = output::open_group(m.file.get(), "run");
    output::write_attribute(run.get(), "status", status);
    output::write_attribute(run.get(), "wall_seconds", wall_seconds);
    output::flush(m.file.get());
  });
}

}  // namespace cosim::tracker::program
