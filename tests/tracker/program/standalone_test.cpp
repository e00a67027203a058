// cosim-tracker --standalone end to end: small scenes run through run_tracker and their run
// files read back. A closed box conserves particles and a zone's crossings account for the
// change inside it; an open outflow and an absorbing obstacle remove them; a periodic box
// keeps them all. And the sidecar's polyhedra, and the fields handed on, are the mesh's cells.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <numeric>

#include "coupler/output/h5_groups.hpp"
#include "coupler/output/h5_handle.hpp"
#include "coupler/output/h5_values.hpp"
#include "coupler/output/series.hpp"
#include "coupler/participant/stage_summary.hpp"
#include "coupler/scene/scene.hpp"
#include "tracker/mesh/voronoi_mesh.hpp"
#include "coupler/output/xdmf.hpp"
#include "tracker/program/mixed_topology.hpp"
#include "tracker/program/cell_fields.hpp"
#include "tracker/program/output_grid.hpp"
#include "tracker/mesh/box_mesh.hpp"
#include "tracker/dsmc/collision.hpp"
#include "tracker/dsmc/species.hpp"
#include "tracker/program/standalone.hpp"

namespace cosim::tracker::program {
namespace {

// Unit box, 100 steps; mass = k_B so that the thermal speed is sqrt(T) m/s.
scene::Scene scene_of_mesh(const std::string& mesh, const std::string& options) {
  return scene::load_scene_from_string(
      "time: {end: 1.0}\ncoupling: {window: 0.1}\noutput: {fields_every: 1}\n"
      "domain: {min: [0, 0, 0], max: [1, 1, 1]}\neffects: [rarefied_gas]\n"
      "participants:\n  tracker:\n    dt: 0.01\n    options:\n      mesh: " +
          mesh + "\n" + options,
      "scene.yaml");
}
scene::Scene scene_of(const std::string& options) { return scene_of_mesh("{type: box, cells: [4, 4, 4]}", options); }

// What the tests read from a run file.
struct RunFileView {
  std::vector<double> particles;                                // per written step
  std::vector<std::vector<double>> count, mean_count, density;  // per written step, per cell
  std::vector<double> moves;                                    // last row
  std::size_t move_columns = 0;
  std::vector<double> hits, absorbed, entered, left;  // rows x objects
  double column(const char* name) const;
};

double RunFileView::column(const char* name) const {
  const auto at = std::find_if(tracking::kMoveCounters.begin(), tracking::kMoveCounters.end(),
                               [&](const tracking::MoveCounter& c) { return std::string_view(c.name) == name; });
  return moves[static_cast<std::size_t>(at - tracking::kMoveCounters.begin())];
}
RunFileView read_run(const std::filesystem::path& path, bool objects) {
  output::Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "open " + path.string());
  const auto series = [&](const std::string& name) { return output::Series::open(file.get(), name).read_all(); };
  RunFileView run;
  run.particles = series("/tracker/particles");
  const std::vector<double> moves = series("/tracker/moves");
  run.moves.assign(moves.end() - static_cast<std::ptrdiff_t>(tracking::kMoveCounters.size()), moves.end());
  output::Handle fields = output::open_group(file.get(), "/fields/tracker");
  for (const std::string& step : output::link_names(fields.get())) {
    if (step == "grid") continue;
    // A box's fields are (nz, ny, nx): read flat, x fastest.
    const auto field = [&](const char* name) { return output::read_array(fields.get(), step + "/" + name); };
    run.count.push_back(field("count"));
    run.mean_count.push_back(field("mean_count"));
    run.density.push_back(field("density"));
  }
  if (objects) {
    run.hits = series("/tracker/objects/hits");
    run.absorbed = series("/tracker/objects/absorbed");
    run.entered = series("/tracker/objects/entered");
    run.left = series("/tracker/objects/left");
  }
  return run;
}

double sum(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0); }

std::filesystem::path out(const char* name) { return std::filesystem::path(::testing::TempDir()) / name; }

TEST(TrackerStandalone, ClosedBoxConservesParticlesAndAZoneCountsItsCrossings) {
  // Diffuse walls, a specular ball in the right half, and a zone that is the left half of
  // the box (its only surface inside is the plane x = 0.5, between cells 1 and 2 along x).
  const scene::Scene scene = scene_of(
      "      boundaries: {default: {kind: diffuse, temperature: 1}}\n"
      "      obstacles:\n"
      "        - {name: ball, shape: {ball: {centre: [0.75, 0.5, 0.5], radius: 0.15}}}\n"
      "        - {name: left, shape: {box: {centre: [0, 0.5, 0.5], half_extents: [0.5, 0.6, 0.6]}}, permeable: true}\n"
      "      particles: {per_cell: 20, temperature: 1, drift: [0.5, 0, 0], mass: 1.380649e-23, seed: 7}\n");
  const RunSummary s = run_tracker(scene, out("closed.h5"));
  const RunFileView run = read_run(out("closed.h5"), true);

  EXPECT_EQ(s.steps, 100u);
  EXPECT_GT(s.seeded, 1200u);  // 1280 draws, those inside the ball dropped
  EXPECT_LT(s.seeded, 1280u);
  EXPECT_EQ(s.remaining, s.seeded);
  ASSERT_EQ(run.particles.size(), 11u);  // steps 0, 10, ..., 100
  ASSERT_EQ(run.count.size(), 11u);
  for (std::size_t k = 0; k < run.count.size(); ++k) {
    EXPECT_EQ(run.particles[k], static_cast<double>(s.seeded));
    EXPECT_EQ(sum(run.count[k]), run.particles[k]);
    EXPECT_NEAR(sum(run.mean_count[k]), run.particles[k], 1e-9);      // conserved: the mean too
    EXPECT_NEAR(run.density[k][5], run.mean_count[k][5] * 64, 1e-9);  // cells of 1/64 m^3
  }
  EXPECT_EQ(run.column("lost"), 0);
  EXPECT_EQ(run.column("removed"), 0);
  EXPECT_EQ(run.column("moves"), 100.0 * static_cast<double>(s.seeded));

  const auto inside_left = [&](std::size_t k) {  // cells along x fastest: i = c % 4
    double n = 0;
    for (std::size_t c = 0; c < 64; ++c)
      if (c % 4 < 2) n += run.count[k][c];
    return n;
  };
  for (std::size_t k = 0; k < run.count.size(); ++k) {
    const std::size_t zone = 2 * k + 1;  // rows x objects: ball, left
    EXPECT_EQ(run.entered[zone] - run.left[zone], inside_left(k) - inside_left(0)) << "row " << k;
    EXPECT_EQ(run.hits[zone], 0);
  }
  EXPECT_GT(run.hits[20], 100);  // the ball, last row
  EXPECT_EQ(run.entered[20], 0);
  EXPECT_GT(run.entered[21], 100);
  EXPECT_GT(run.left[21], 100);
}

TEST(TrackerStandalone, OpenOutflowAndAnAbsorbingObstacleRemoveParticles) {
  const scene::Scene scene = scene_of(
      "      boundaries: {default: {kind: specular}, x_max: {kind: open}}\n"
      "      obstacles:\n"
      "        - {name: sink, shape: {ball: {centre: [0.5, 0.5, 0.5], radius: 0.2}}, wall: {kind: open}}\n"
      "      particles: {total: 2000, temperature: 0.1, drift: [2, 0, 0], mass: 1.380649e-23}\n");
  const RunSummary s = run_tracker(scene, out("outflow.h5"));
  const RunFileView run = read_run(out("outflow.h5"), true);

  EXPECT_EQ(s.seeded, 2000u);
  EXPECT_LT(s.remaining, 100u);  // drifting 2 box lengths along x: nearly all gone
  EXPECT_EQ(run.particles.back(), static_cast<double>(s.remaining));
  for (std::size_t k = 0; k < run.count.size(); ++k) EXPECT_EQ(sum(run.count[k]), run.particles[k]);
  for (std::size_t k = 1; k < run.particles.size(); ++k) EXPECT_LE(run.particles[k], run.particles[k - 1]);
  EXPECT_EQ(run.column("removed"), static_cast<double>(s.seeded - s.remaining));
  EXPECT_EQ(run.column("lost"), 0);
  EXPECT_GT(run.absorbed.back(), 50);  // the ball's shadow: about its cross-section's share
  EXPECT_EQ(run.absorbed.back(), run.hits.back());
  EXPECT_LT(run.absorbed.back(), run.column("removed"));  // the rest left through x_max

  // One object and six patches: tables of rows x objects (patches) all the same, so that
  // [:, i] reads a column whatever the count.
  output::Handle file(H5Fopen(out("outflow.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "open");
  const std::vector<hsize_t> rows_by_one{run.particles.size(), 1}, rows_by_three{run.particles.size(), 3};
  for (const char* name : {"hits", "absorbed", "entered", "left", "released", "energy"})
    EXPECT_EQ(output::array_dims(file.get(), std::string("/tracker/objects/") + name), rows_by_one) << name;
  EXPECT_EQ(output::array_dims(file.get(), "/tracker/objects/impulse"), rows_by_three);
  EXPECT_EQ(output::array_dims(file.get(), "/tracker/patches/hits").size(), 2u);
}

// Guards against: the program losing particles on periodic faces of a tetrahedral box.
TEST(TrackerStandalone, PeriodicBoxKeepsEveryParticle) {
  // No walls at all: every side linked, the particles drift through them around a ball.
  const scene::Scene scene = scene_of_mesh(
      "{type: box, cells: [4, 3, 2], tetrahedra: true, periodic: [true, true, true]}",
      "      obstacles:\n"
      "        - {name: ball, shape: {ball: {centre: [0.5, 0.5, 0.5], radius: 0.3}}, wall: {kind: diffuse, "
      "temperature: 1}}\n"
      "      particles: {total: 1000, temperature: 1, drift: [3, 1, 0], mass: 1.380649e-23}\n");
  const RunSummary s = run_tracker(scene, out("periodic.h5"));
  const RunFileView run = read_run(out("periodic.h5"), true);
  EXPECT_EQ(s.remaining, 1000u);
  for (std::size_t k = 0; k < run.count.size(); ++k) EXPECT_EQ(sum(run.count[k]), 1000);
  EXPECT_EQ(run.column("lost"), 0);
  EXPECT_GT(run.column("faces_crossed"), 1000);
  EXPECT_GT(run.hits.back(), 500);  // 3 box lengths along x through a ball of a third of the section
}

TEST(TrackerStandalone, WritesTheLastStepWithoutFieldsEveryAndNoObstacles) {
  scene::Scene scene = scene_of(
      "      boundaries: {default: {kind: specular}}\n"
      "      particles: {per_cell: 1, temperature: 1, mass: 1.380649e-23}\n");
  scene.output.fields_every = 0;  // only the start and the end
  const RunSummary s = run_tracker(scene, out("bare.h5"));
  const RunFileView run = read_run(out("bare.h5"), false);
  ASSERT_EQ(run.particles.size(), 2u);
  EXPECT_EQ(run.particles[1], 64);
  EXPECT_EQ(s.remaining, 64u);
  EXPECT_TRUE(std::filesystem::exists(out("bare.xmf")));
  // The step's stages timed: moves and sorts took time, collisions none (there are none).
  EXPECT_GT(s.stages[step::Stage::move], 0.0);
  EXPECT_GT(s.stages[step::Stage::sort], 0.0);
  EXPECT_EQ(s.stages[step::Stage::collide], 0.0);
  double stages = 0;
  for (std::size_t k = 0; k < step::kStageNames.size(); ++k) stages += s.stages[static_cast<step::Stage>(k)];
  EXPECT_LE(stages + s.setup_seconds, s.wall_seconds);
  const std::string summary = participant::stage_summary(step::kStageNames, s.stages.all());
  EXPECT_EQ(summary.find("collide"), std::string::npos) << summary;
  EXPECT_NE(summary.find("move "), std::string::npos) << summary;
}

// Guards against: a box's volumes, written a slab of cells at a time, put in the wrong
// place (a graded box: every cell's differs from its neighbours').
TEST(TrackerStandalone, AGradedBoxsVolumesAreShapedAsItsFields) {
  scene::Scene scene = scene_of_mesh("{type: box, cells: [3, 2, 4], ratio: [2, 3, 0.5]}",
                                     "      boundaries: {default: {kind: specular}}\n"
                                     "      particles: {per_cell: 1, temperature: 1, mass: 1.380649e-23}\n");
  scene.output.fields_every = 0;
  run_tracker(scene, out("graded.h5"));
  output::Handle file(H5Fopen(out("graded.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "open graded.h5");
  EXPECT_EQ(output::array_dims(file.get(), "/fields/tracker/grid/volume"), (std::vector<hsize_t>{4, 2, 3}));
  mesh::BoxSpec spec;
  for (int a = 0; a < 3; ++a)
    spec.axes[a] = {.min = 0, .max = 1, .cells = std::array{3, 2, 4}[a], .ratio = std::array{2.0, 3.0, 0.5}[a]};
  const std::vector<double> volume = output::read_array(file.get(), "/fields/tracker/grid/volume");
  EXPECT_EQ(volume, step::cell_volumes(spec));
  EXPECT_NEAR(sum(volume), 1.0, 1e-14);
}

// DSMC in a closed box (argon, VSS, specular walls): every particle kept, and the
// collisions per step those of an equilibrium gas, 0.5 N n <sigma g>.
TEST(TrackerStandalone, CollisionsAtTheEquilibriumRate) {
  const scene::Scene scene = scene::load_scene_from_string(
      "time: {end: 3.5e-7}\ncoupling: {window: 3.5e-7}\noutput: {fields_every: 0}\n"
      "domain: {min: [0, 0, 0], max: [1.0e-4, 1.0e-4, 1.0e-4]}\neffects: [rarefied_gas]\n"
      "participants:\n  tracker:\n    dt: 7.0e-9\n    options:\n"
      "      mesh: {type: box, cells: [10, 10, 10]}\n"
      "      boundaries: {default: {kind: specular}}\n"
      "      collisions: {species: Ar, model: vss}\n"
      "      particles: {per_cell: 20, temperature: 273.15, mass: 6.63e-26, weight: 3.5e6, seed: 3}\n",
      "scene.yaml");
  const RunSummary s = run_tracker(scene, out("collide.h5"));
  EXPECT_EQ(s.remaining, s.seeded);
  EXPECT_EQ(s.moves.lost, 0);
  const dsmc::Species& argon = dsmc::read_species(dsmc::default_species_file()).at("Ar");
  const double n = 20.0 * 3.5e6 / 1e-15;  // real molecules per m^3: 20 simulators per (1e-5 m)^3
  const double expected = 0.5 * static_cast<double>(s.seeded) * n *
                          dsmc::CollisionModel::from_species(argon, dsmc::Model::vss).mean_sigma_g(273.15) * 7.0e-9 *
                          50;
  std::printf("closed box, VSS argon: %lld collisions in 50 steps, equilibrium %.0f\n",
              static_cast<long long>(s.collisions), expected);
  EXPECT_NEAR(static_cast<double>(s.collisions) / expected, 1.0, 0.02);
}

// Two shipped configs, shortened: the sphere-cluster channel and the open-cell foam
// keep every particle (periodic sides, mirrors, re-emitting walls), lose none, and their
// walls are hit; the gas drifting along +x pushes the cluster along +x.
// `window` empty: one window of `end`.
scene::Scene shortened_config(const std::string& name, const std::string& end, std::string window_length = "") {
  if (window_length.empty()) window_length = end;
  const std::filesystem::path file = std::filesystem::path(COSIM_CONFIGS_DIR) / (name + ".yaml");
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  const std::regex time_end(R"(time:\n  end: [^\n]+)"), window(R"(coupling:\n  window: [^\n]+)");
  EXPECT_TRUE(std::regex_search(text.str(), time_end) && std::regex_search(text.str(), window)) << name;
  const std::string shortened = std::regex_replace(text.str(), time_end, "time:\n  end: " + end);
  return scene::load_scene_from_string(std::regex_replace(shortened, window, "coupling:\n  window: " + window_length),
                                       file.string());
}

TEST(TrackerConfigs, SphereClusterChannelFoamAndSphereStreamRun) {
  const RunSummary channel = run_tracker(shortened_config("tracker-sphere-cluster", "2.0e-5"), out("channel.h5"));
  const RunFileView c = read_run(out("channel.h5"), true);
  EXPECT_EQ(channel.remaining, channel.seeded);
  EXPECT_EQ(c.column("lost"), 0);
  EXPECT_GT(c.hits[c.hits.size() - 2], 100);  // the cluster, first of the two objects
  output::Handle file(H5Fopen(out("channel.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "open");
  const std::vector<double> impulse = output::Series::open(file.get(), "/tracker/objects/impulse").read_all();
  EXPECT_GT(impulse[impulse.size() - 6], 0.0);  // the cluster's x, last row
  EXPECT_GT(c.entered.back(), 0);               // the wake zone

  const RunSummary foam = run_tracker(shortened_config("tracker-foam", "2.0e-5"), out("foam.h5"));
  const RunFileView f = read_run(out("foam.h5"), true);
  EXPECT_EQ(foam.remaining, foam.seeded);
  EXPECT_EQ(f.column("lost"), 0);
  EXPECT_GT(f.hits.back(), 1000);
  for (std::size_t k = 0; k < f.count.size(); ++k) EXPECT_EQ(sum(f.count[k]), static_cast<double>(foam.seeded));
  // Argon at 300 K at rest among struts re-emitting at 300 K stays at 300 K on average.
  output::Handle foam_file(H5Fopen(out("foam.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "open");
  const auto last = [&](const char* name) {
    std::vector<std::string> steps = output::link_names(output::open_group(foam_file.get(), "/fields/tracker").get());
    std::erase(steps, "grid");
    return output::read_array(foam_file.get(), "/fields/tracker/" + steps.back() + "/" + name);
  };
  const std::vector<double> temperature = last("temperature"), weight = last("mean_count");
  double mean = 0.0;
  for (std::size_t c = 0; c < weight.size(); ++c) mean += temperature[c] * weight[c] / sum(weight);
  EXPECT_NEAR(mean, 300.0, 15.0);

  // The sphere in a rarefied stream: seeded as the stream and fed by the inflow, collisions
  // on, the sphere hit.
  const RunSummary stream = run_tracker(shortened_config("tracker-sphere-stream", "1.0e-3"), out("stream.h5"));
  const RunFileView r = read_run(out("stream.h5"), true);
  EXPECT_EQ(r.column("lost"), 0);
  EXPECT_GT(stream.seeded, 100000u);
  EXPECT_GT(stream.injected, 20000u);  // a quarter of a box volume through the upstream side
  EXPECT_GT(stream.collisions, 10000);
  EXPECT_GT(r.hits.back(), 100);
  EXPECT_EQ(stream.remaining, stream.seeded + stream.injected - static_cast<std::size_t>(r.column("removed")));
}

TEST(TrackerConfigs, FoamFlowRunsDownThePressureDrop) {
  // configs/tracker-foam-flow.yaml for 100 steps from uniform gas at the mean density
  // (3.6e21 m^-3): the plenums tend to their reservoirs (4.83e21 below the foam, 2.41e21
  // above), so the gas is denser upstream than downstream, and it flows downstream into
  // the outlet zone; nothing lost, every particle accounted for.
  const RunSummary s = run_tracker(shortened_config("tracker-foam-flow", "7.5e-5"), out("foam-flow.h5"));
  const RunFileView r = read_run(out("foam-flow.h5"), true);
  EXPECT_EQ(r.column("lost"), 0);
  EXPECT_GT(s.collisions, 10000);
  EXPECT_GT(r.hits[r.hits.size() - 2], 1000);  // the foam, first of the two objects
  EXPECT_EQ(s.remaining, s.seeded + s.injected - static_cast<std::size_t>(r.column("removed")));
  // Mean density of the 6 layers of 16 x 16 cells below the foam and the 6 above (cells x
  // fastest, z slowest), averaged over the run.
  const auto plenum = [&](std::size_t first_layer) {
    double sum = 0;
    for (std::size_t c = 256 * first_layer; c < 256 * (first_layer + 6); ++c) sum += r.density.back()[c];
    return sum / (256 * 6);
  };
  const double upstream = plenum(0), downstream = plenum(22);
  std::printf("foam flow: plenum densities %.3g (reservoir 4.83e21) and %.3g (2.41e21) m^-3, net %g into the outlet\n",
              upstream, downstream, r.entered.back() - r.left.back());
  EXPECT_GT(upstream, 4.0e21);                       // measured 4.5e21
  EXPECT_LT(downstream, 3.2e21);                     // measured 2.75e21
  EXPECT_GT(r.entered.back() - r.left.back(), 500);  // the outlet zone, last object: 1632
}

TEST(TrackerConfigs, CouettePlatesFeelEqualAndOppositeShearBetweenTheLimits) {
  // configs/tracker-couette.yaml for 0.1 ms (2.5 times H^2 / nu): the plates' tallies over
  // the last three windows, once the profile has settled.
  const RunSummary s = run_tracker(shortened_config("tracker-couette", "1.0e-4", "2.0e-5"), out("couette.h5"));
  EXPECT_EQ(s.remaining, s.seeded);
  output::Handle file(H5Fopen(out("couette.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "open");
  const auto series = [&](const std::string& name) { return output::Series::open(file.get(), name).read_all(); };
  const std::vector<double> time = series("/tracker/time"), impulse = series("/tracker/patches/impulse");
  const std::vector<double> area = output::read_array(file.get(), "/tracker/patches/area");
  ASSERT_EQ(time.size(), 6u);
  ASSERT_EQ(area.size(), 6u);  // x_min, x_max, y_min, y_max, z_min, z_max
  const auto shear = [&](std::size_t patch) {
    const std::size_t last = 3 * (6 * 5 + patch), settled = 3 * (6 * 2 + patch);
    return (impulse[last] - impulse[settled]) * 6.63e-26 * 1.04e6 / (area[patch] * (time[5] - time[2]));
  };
  const double lower = shear(2), upper = shear(3);
  // Argon at 273 K: mu 2.117e-5 Pa s, lambda 0.129 mm (Kn 0.13), U 300 m/s, H 1 mm.
  const double slip = 2.117e-5 * 300 / (1e-3 + 2 * 1.111 * 0.129e-3), free_molecular = 24.6;
  std::printf(
      "Couette, Kn 0.13: shear %.3f and %.3f Pa on the plates; slip-corrected continuum %.3f, "
      "free-molecular %.1f\n",
      lower, -upper, slip, free_molecular);
  EXPECT_NEAR(lower, -upper, 0.06 * lower);  // about 9000 hits per plate: 2 % each
  EXPECT_NEAR(lower / slip, 1.0, 0.1);       // first-order slip at Kn 0.13: a few % low
  EXPECT_NEAR(area[2], 4e-10, 1e-22);
}

TEST(PolyhedraXdmf, MixedTopologyReadsBackAsTheCells) {
  // A Voronoi mesh: cells of many faces, faces of many vertices.
  std::vector<Vec3> sites;
  tracking::Random random(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 40; ++i) sites.emplace_back(unit(random), unit(random), unit(random));
  const mesh::Mesh mesh = mesh::voronoi_mesh(sites, {});
  const std::vector<std::int64_t> topology = mixed_topology(mesh);
  std::size_t at = 0;
  for (Index c = 0; c < mesh.cell_count(); ++c) {
    ASSERT_EQ(topology[at++], 16);  // XDMF Polyhedron
    ASSERT_EQ(topology[at++], mesh.cell_faces[c + 1] - mesh.cell_faces[c]);
    for (Index f = mesh.cell_faces[c]; f < mesh.cell_faces[c + 1]; ++f) {
      ASSERT_EQ(topology[at++], mesh.vertex_count(f));
      for (Index k = mesh.face_vertex_begin[f]; k < mesh.face_vertex_begin[f + 1]; ++k)
        EXPECT_EQ(topology[at++], mesh.face_vertex_index[k]);
    }
  }
  EXPECT_EQ(at, topology.size());

  const std::string doc = output::xdmf_document(
      "a&b.h5", {{.name = "tracker",
                  .grid_group = "/fields/tracker/grid",
                  .cells = {},
                  .steps = {{"/fields/tracker/000000", 0.5, {{"count", 1}, {"velocity", 3}}}},
                  .polyhedra = {.cells = 40, .vertices = mesh.vertices.size(), .topology_size = topology.size()}}});
  EXPECT_NE(doc.find("TopologyType=\"Mixed\" NumberOfElements=\"40\""), std::string::npos);
  EXPECT_NE(doc.find("Dimensions=\"" + std::to_string(topology.size()) + "\" NumberType=\"Int\""), std::string::npos);
  EXPECT_NE(doc.find("Dimensions=\"40 3\" NumberType=\"Float\""), std::string::npos);  // the vector field
  EXPECT_NE(doc.find("a&amp;b.h5:/fields/tracker/000000/count"), std::string::npos);
  EXPECT_NE(doc.find("<Time Value=\"0.5\"/>"), std::string::npos);
}

// What the tracker hands the run file (and the coupler): its cells as a grid that the
// writer's checks accept, with each sample's fields in cell order.
TEST(TrackerFields, TheSamplesPerCellInCellOrder) {
  std::vector<tracking::CellMoments> moments(12);
  std::vector<double> count(12);
  for (std::size_t c = 0; c < 12; ++c) {
    count[c] = double(c);
    moments[c] = {.count = 0.5 * double(c),
                  .number_density = 1e20,
                  .velocity = Vec3(double(c), 0, -1),
                  .temperature = 300,
                  .pressure = 0.4};
  }
  const std::vector<field::CellField> fields = cell_fields(moments, count);
  std::vector<std::string> names;
  for (const field::CellField& f : fields) {
    names.push_back(f.name);
    EXPECT_EQ(f.values.size(), 12u * static_cast<std::size_t>(f.components)) << f.name;
  }
  EXPECT_EQ(names, (std::vector<std::string>{"count", "mean_count", "density", "velocity", "temperature", "pressure"}));
  EXPECT_EQ(fields[0].values, count);
  EXPECT_EQ(fields[1].values[7], 3.5);
  EXPECT_EQ(fields[3].components, 3);
  EXPECT_EQ(fields[3].values[3 * 7], 7.0);
  EXPECT_EQ(fields[3].values[3 * 7 + 2], -1.0);
}

// The patch areas and cell volumes the mesh's own geometry gives (faces' areas, cells'
// volumes), to compare with what a box's nodes give without the mesh.
void expect_geometry_of(const OutputGrid& grid, const mesh::Mesh& mesh) {
  const OutputGrid from_mesh = output_grid(mesh);
  // A box of hexahedra holds no volume per cell: the writer takes them from the box.
  EXPECT_EQ(grid.volume.empty(), grid.box.has_value());
  const std::vector<double> volume = grid.box ? step::cell_volumes(*grid.box) : grid.volume;
  ASSERT_EQ(volume.size(), from_mesh.volume.size());
  for (std::size_t c = 0; c < volume.size(); ++c)
    EXPECT_NEAR(volume[c], from_mesh.volume[c], 1e-14 * from_mesh.volume[c]) << "cell " << c;
  EXPECT_EQ(grid.patches, from_mesh.patches);
  ASSERT_EQ(grid.patch_area.size(), from_mesh.patch_area.size());
  for (std::size_t p = 0; p < grid.patch_area.size(); ++p)
    EXPECT_NEAR(grid.patch_area[p], from_mesh.patch_area[p], 1e-14) << grid.patches[p];
}

// Any mesh is shown as its polyhedra; a box of hexahedra as the rectilinear grid of its nodes
// (graded axes too), a box of tetrahedra as the polyhedra box_mesh would give, both without
// building the mesh.
TEST(OutputGrid, ABoxIsShownWithoutItsMesh) {
  mesh::BoxSpec spec;
  spec.axes = {mesh::AxisSpacing{.min = -1, .max = 2, .cells = 3, .ratio = 2.5}, mesh::AxisSpacing{.cells = 2},
               mesh::AxisSpacing{.nodes = {0.0, 0.1, 0.5}}};
  spec.periodic = {false, true, false};
  const mesh::Mesh hexahedra = mesh::box_mesh(spec);
  const OutputGrid rectilinear = output_grid(spec);
  const auto& nodes = std::get<field::RectilinearGrid>(rectilinear.grid);
  EXPECT_EQ(field::grid_problem(rectilinear.grid), "");
  EXPECT_EQ(nodes.nodes[0], mesh::axis_nodes(spec.axes[0]));
  EXPECT_EQ(nodes.nodes[2], spec.axes[2].nodes);
  expect_geometry_of(rectilinear, hexahedra);
  EXPECT_EQ(rectilinear.patch_area[2], 0.0);  // the periodic y sides have no walls

  spec.tetrahedra = true;
  const mesh::Mesh tetrahedra = mesh::box_mesh(spec);
  const OutputGrid polyhedra = output_grid(spec);
  const auto& cells = std::get<field::PolyhedralGrid>(polyhedra.grid);
  EXPECT_EQ(field::grid_problem(polyhedra.grid), "");
  const OutputGrid from_mesh = output_grid(tetrahedra);
  const auto& whole = std::get<field::PolyhedralGrid>(from_mesh.grid);
  EXPECT_EQ(cells.cells, 72u);
  EXPECT_EQ(cells.topology, whole.topology);
  EXPECT_EQ(cells.vertices, whole.vertices);
  expect_geometry_of(polyhedra, tetrahedra);
}

}  // namespace
}  // namespace cosim::tracker::program
