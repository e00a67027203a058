#include "tracker/program/tracker_file.hpp"

#include <hdf5.h>

#include <cstdio>

#include "cosim_git_hash.hpp"
#include "output/h5_groups.hpp"
#include "output/h5_handle.hpp"
#include "output/h5_values.hpp"
#include "output/series.hpp"
#include "output/in_file.hpp"
#include "output/text.hpp"
#include "output/xdmf.hpp"
#include "tracker/program/mixed_topology.hpp"

namespace cosim::tracker {
namespace {

using output::Handle;
using output::Series;

const std::vector<std::string> kMoveColumns{"moves",     "faces_crossed", "zero_time_events", "boundary_hits",
                                            "relocations", "cycles_broken", "stalled",          "removed",
                                            "lost",       "object_events", "primitive_tests"};

std::vector<std::uint64_t> columns_of(const MoveTally& t) {
  const long long v[] = {t.moves,         t.faces_crossed, t.zero_time_events, t.boundary_hits,
                         t.relocations,   t.cycles_broken, t.stalled,          t.removed,
                         t.lost,          t.object_events, t.primitive_tests};
  return {std::begin(v), std::end(v)};
}

// Zero-padded, so the step groups list in time order wherever names are sorted.
std::string step_name(std::uint64_t step) {
  char text[24];
  std::snprintf(text, sizeof text, "%06llu", static_cast<unsigned long long>(step));
  return text;
}

// output/ writes float64 arrays only; the topology is integers.
void write_int64_array(hid_t group, const std::string& name, const std::vector<std::int64_t>& values) {
  const hsize_t n = values.size();
  Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose, "dataspace of " + name);
  Handle ds(H5Dcreate2(group, name.c_str(), H5T_NATIVE_INT64, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
            H5Dclose, "create " + output::child_path(group, name));
  output::check(H5Dwrite(ds.get(), H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()),
                "write " + output::child_path(group, name));
}

}  // namespace

struct TrackerFile::Impl {
  std::filesystem::path path;
  Handle file;
  std::size_t objects = 0;
  std::vector<Series> rows;     // step, time, particles, moves
  std::vector<Series> tallies;  // hits, absorbed, entered, left, released, impulse, angular_impulse, energy
  std::vector<double> volume;  // per cell, for the density
  output::XdmfSeries sidecar;
};

TrackerFile::TrackerFile(const std::filesystem::path& path, const scene::Scene& scene, const Mesh& mesh,
                         const std::vector<std::string>& object_names)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.path = path;
  m.objects = object_names.size();
  m.volume = mesh.volume;
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
    Handle fields = output::create_group(file, "fields");
    Handle tracker = output::create_group(fields.get(), "tracker");
    Handle grid = output::create_group(tracker.get(), "mesh");
    std::vector<double> xyz;
    for (const Vec3& v : mesh.vertices) xyz.insert(xyz.end(), {v.x(), v.y(), v.z()});
    output::write_array(grid.get(), "vertices", {mesh.vertices.size(), 3}, xyz.data());
    const std::vector<std::int64_t> topology = mixed_topology(mesh);
    write_int64_array(grid.get(), "topology", topology);
    output::write_array(grid.get(), "volume", {mesh.volume.size()}, mesh.volume.data());
    m.sidecar = {.name = "tracker",
                 .grid_group = "/fields/tracker/mesh",
                 .cells = {},
                 .steps = {},
                 .polyhedra = {.cells = static_cast<std::size_t>(mesh.cell_count()),
                               .vertices = mesh.vertices.size(),
                               .topology_size = topology.size()}};

    Handle series = output::create_group(file, "tracker");
    m.rows.push_back(Series::create(series.get(), "step", 1, H5T_NATIVE_UINT64));
    m.rows.push_back(Series::create(series.get(), "time", 1, H5T_NATIVE_DOUBLE));
    m.rows.push_back(Series::create(series.get(), "particles", 1, H5T_NATIVE_UINT64));
    m.rows.push_back(Series::create(series.get(), "moves", kMoveColumns.size(), H5T_NATIVE_UINT64));
    {
      Handle moves(H5Dopen2(series.get(), "moves", H5P_DEFAULT), H5Dclose, "open /tracker/moves");
      output::write_attribute(moves.get(), "columns", kMoveColumns);
    }
    Handle objects = output::create_group(series.get(), "objects");
    output::write_attribute(objects.get(), "names", object_names);
    // A dataset needs at least one column: with no objects the tallies are not written.
    if (m.objects > 0) {
      for (const char* name : {"hits", "absorbed", "entered", "left", "released"})
        m.tallies.push_back(Series::create(objects.get(), name, m.objects, H5T_NATIVE_UINT64));
      m.tallies.push_back(Series::create(objects.get(), "impulse", 3 * m.objects, H5T_NATIVE_DOUBLE));
      m.tallies.push_back(Series::create(objects.get(), "angular_impulse", 3 * m.objects, H5T_NATIVE_DOUBLE));
      m.tallies.push_back(Series::create(objects.get(), "energy", m.objects, H5T_NATIVE_DOUBLE));
    }
    output::flush(file);
  });
}

TrackerFile::TrackerFile(TrackerFile&&) noexcept = default;
TrackerFile::~TrackerFile() = default;

void TrackerFile::write(const Sample& s) {
  Impl& m = *impl_;
  output::in_file(m.path, [&] {
    const hid_t file = m.file.get();
    const std::string group = "/fields/tracker/" + step_name(s.step);
    const std::size_t cells = m.volume.size();
    if (s.count.size() != cells || s.moments.size() != cells || s.objects.size() != m.objects)
      throw output::ObjectError(group + ": the sample does not fit the mesh or the objects");
    {
      Handle step = output::create_group(file, group);
      output::write_attribute(step.get(), "time", s.time);
      std::vector<double> mean_count, density, velocity, temperature, pressure;
      for (const CellMoments& c : s.moments) {
        mean_count.push_back(c.count);
        density.push_back(c.number_density);
        velocity.insert(velocity.end(), {c.velocity.x(), c.velocity.y(), c.velocity.z()});
        temperature.push_back(c.temperature);
        pressure.push_back(c.pressure);
      }
      output::write_array(step.get(), "count", {cells}, s.count.data());
      output::write_array(step.get(), "mean_count", {cells}, mean_count.data());
      output::write_array(step.get(), "density", {cells}, density.data());
      output::write_array(step.get(), "velocity", {cells, 3}, velocity.data());
      output::write_array(step.get(), "temperature", {cells}, temperature.data());
      output::write_array(step.get(), "pressure", {cells}, pressure.data());
    }
    m.sidecar.steps.push_back({group, s.time,
                               {{"count", 1}, {"mean_count", 1}, {"density", 1}, {"velocity", 3}, {"temperature", 1},
                                {"pressure", 1}}});

    m.rows[0].append(&s.step);
    m.rows[1].append(&s.time);
    m.rows[2].append(&s.particles);
    m.rows[3].append(columns_of(s.moves).data());
    if (m.objects > 0) {
      std::vector<std::vector<std::uint64_t>> counts(5);
      std::vector<double> impulse, angular_impulse, energy;
      for (const ObstacleTally& t : s.objects) {
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
    output::flush(file);
  });
  output::write_replacing(std::filesystem::path(m.path).replace_extension(".xmf"),
                          output::xdmf_document(m.path.filename().string(), {m.sidecar}));
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

}  // namespace cosim::tracker
