// The tracker's gas over two MPI ranks (run under `mpirun -n 2`): the partition is the
// same on both ranks, migration delivers every particle with its states to the owner of its
// cell (one left in a ghost, even a second-layer one, with its states evaluated anew there),
// and a scene run on two ranks gives one rank's answer within the statistical
// scatter of the two runs (different random streams), computed per quantity below. A
// repeated coupling window on two ranks gives the same forces after restore(). A gas without
// random draws writes the same particles, or the same sample of them, on two ranks as on one.
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <random>
#include <regex>
#include <sstream>

#include "coupler/output/h5_handle.hpp"
#include "coupler/scene/error.hpp"
#include "coupler/output/h5_values.hpp"
#include "coupler/output/series.hpp"
#include "coupler/participant/mpi_team.hpp"
#include "tracker/mesh/box_mesh.hpp"
#include "tracker/parallel/decomposition.hpp"
#include "tracker/parallel/partition.hpp"
#include "tracker/program/adapter.hpp"
#include "tracker/program/scene_tracker.hpp"
#include "tracker/program/standalone.hpp"
#include "tracker/step/seed_particles.hpp"
#include "tracker/step/simulation.hpp"
#include "tracker/step/state_array.hpp"

namespace cosim::tracker::parallel {
namespace {

int rank() {
  int r = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

TEST(Decomposition, TheSameOnBothRanksAndMetisAnswer) {
  const mesh::Mesh mesh = mesh::box_mesh(mesh::cube(10));
  const Decomposition d(mesh, Ranks(MPI_COMM_WORLD));
  ASSERT_EQ(d.ranks().size(), 2) << "run this test with mpirun -n 2";
  std::vector<int> owners = d.owners().saved(), low(owners.size()), high(owners.size());
  MPI_Allreduce(owners.data(), low.data(), static_cast<int>(owners.size()), MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  MPI_Allreduce(owners.data(), high.data(), static_cast<int>(owners.size()), MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  EXPECT_EQ(low, high);
  EXPECT_EQ(owners, partition_cells(mesh, 2));
}

TEST(Migration, EveryParticleReachesItsCellsOwnerWithItsStates) {
  const mesh::Mesh mesh = mesh::box_mesh(mesh::cube(6));
  Decomposition d(mesh, Ranks(MPI_COMM_WORLD));
  // 1000 particles per rank in random cells; states: an id unique over the ranks and its
  // complement, so a record mixed up on the way shows.
  tracking::Swarm swarm(2);
  std::mt19937_64 random(static_cast<std::uint64_t>(rank()) + 7);
  std::uniform_int_distribution<Index> cell(0, mesh.cell_count() - 1);
  long long leaving = 0;
  for (std::uint64_t i = 0; i < 1000; ++i) {
    const Index c = cell(random);
    const std::uint64_t id = static_cast<std::uint64_t>(rank()) * 1000 + i;
    swarm.add({mesh.centroid[c], {static_cast<double>(id), 0, 0}, c}, std::vector<csg::State>{id, ~id});
    leaving += d.owns(c) ? 0 : 1;
  }
  EXPECT_EQ(static_cast<long long>(d.migrate(swarm)), leaving);
  long long ids = 0;
  for (std::size_t i = 0; i < swarm.size(); ++i) {
    const tracking::Particle p = swarm.particle(i);
    EXPECT_TRUE(d.owns(p.cell));
    EXPECT_EQ(p.x, mesh.centroid[p.cell]);
    EXPECT_EQ(swarm.states(i)[0], static_cast<std::uint64_t>(p.v.x()));
    EXPECT_EQ(swarm.states(i)[1], ~swarm.states(i)[0]);
    ids += static_cast<long long>(swarm.states(i)[0]);
  }
  EXPECT_EQ(d.ranks().sum(static_cast<long long>(swarm.size())), 2000);
  EXPECT_EQ(d.ranks().sum(ids), 1999LL * 2000 / 2);  // every id once
}

// Two gases by region, overlapping, one cut by the tetrahedra and by the wall ball.
constexpr const char* kRegions =
    "{mass: 6.63e-26, weight: 5.0e15, seed: 4, regions: ["
    "{region: {ball: {centre: [0.7, 0.5, 0.5], radius: 0.35}}, number_density: 2.0e19, temperature: 300,"
    " velocity: [100, 0, 0]},"
    " {region: {box: {centre: [0.3, 0.5, 0.5], half_extents: [0.3, 0.5, 0.5]}}, number_density: 1.0e19,"
    " temperature: 50}]}";

// Each rank's particles are, in order and to the bit, those a one-rank seeding puts in its cells.
TEST(Seeding, TwoRanksSeedWhatOneRankSeeds) {
  for (const char* particles :
       {"{per_cell: 7, temperature: 300, mass: 6.63e-26, seed: 4}",
        "{total: 5000, temperature: 300, drift: [100, 0, 0], mass: 6.63e-26, seed: 4}", kRegions}) {
    const program::TrackerScene t = program::read_tracker(scene::load_scene_from_string(
        "time: {end: 0.1}\ncoupling: {window: 0.1}\ndomain: {min: [0, 0, 0], max: [1, 1, 1]}\n"
        "effects: [rarefied_gas]\nparticipants:\n  tracker:\n    dt: 0.01\n    options:\n"
        "      mesh: {type: box, cells: [9, 7, 5], tetrahedra: true}\n      boundaries: {default: {kind: specular}}\n"
        "      obstacles:\n        - {name: ball, shape: {ball: {centre: [0.4, 0.5, 0.5], radius: 0.3}}}\n"
        "      particles: " +
            std::string(particles) + "\n",
        "seeding.yaml"));
    const Decomposition two(*t.mesh, Ranks(MPI_COMM_WORLD));
    const tracking::Swarm mine =
        step::seed_particles(*t.mesh, t.obstacles, t.particles, two, step::volumes_of(*t.mesh));
    const tracking::Swarm all =
        step::seed_particles(*t.mesh, t.obstacles, t.particles, Decomposition(*t.mesh, {}), step::volumes_of(*t.mesh));
    std::size_t k = 0;
    for (std::size_t i = 0; i < all.size(); ++i) {
      if (!two.owns(all.cell(i))) continue;
      ASSERT_LT(k, mine.size()) << particles;
      const tracking::Particle a = all.particle(i), b = mine.particle(k);
      EXPECT_TRUE(a.x == b.x && a.v == b.v && a.cell == b.cell && all.states(i)[0] == mine.states(k)[0]) << particles;
      ++k;
    }
    EXPECT_EQ(k, mine.size()) << particles;
    EXPECT_EQ(two.ranks().sum(static_cast<long long>(mine.size())), static_cast<long long>(all.size())) << particles;
  }
}

// The gas by region on each rank's part of a box (the cells' volumes from the box's nodes,
// not from the part): as many particles as on one rank holding the whole box, at the same
// places with the same velocities (their sums, to round-off).
TEST(Seeding, RegionsOnTheRanksPartsAsOnOne) {
  const scene::Scene scene = scene::load_scene_from_string(
      "time: {end: 0.1}\ncoupling: {window: 0.1}\ndomain: {min: [0, 0, 0], max: [1, 1, 1]}\n"
      "effects: [rarefied_gas]\nparticipants:\n  tracker:\n    dt: 0.01\n    options:\n"
      "      mesh: {type: box, cells: [13, 6, 5]}\n      boundaries: {default: {kind: specular}}\n"
      "      particles: " +
          std::string(kRegions) + "\n",
      "regions.yaml");
  const auto sums = [](const step::Simulation& gas, MPI_Comm comm) {
    std::array<double, 7> s{};
    for (std::size_t i = 0; i < gas.swarm().size(); ++i) {
      const tracking::Particle p = gas.swarm().particle(i);
      for (int a = 0; a < 3; ++a) {
        s[static_cast<std::size_t>(a)] += p.x[a];
        s[3 + static_cast<std::size_t>(a)] += p.v[a];
      }
      s[6] += 1;
    }
    MPI_Allreduce(MPI_IN_PLACE, s.data(), 7, MPI_DOUBLE, MPI_SUM, comm);
    return s;
  };
  const Ranks world(MPI_COMM_WORLD);
  program::TrackerScene part = program::read_tracker(scene, world);
  ASSERT_TRUE(part.mesh->partial);
  const step::Simulation two(std::move(part), world);
  const std::array<double, 7> on_two = sums(two, MPI_COMM_WORLD);
  if (rank() != 0) return;
  const step::Simulation one(program::read_tracker(scene), Ranks(MPI_COMM_SELF));
  const std::array<double, 7> on_one = sums(one, MPI_COMM_SELF);
  EXPECT_GT(on_one[6], 1000);
  EXPECT_EQ(on_two[6], on_one[6]);  // the count
  for (std::size_t k = 0; k < 6; ++k) EXPECT_NEAR(on_two[k], on_one[k], 1e-9 * std::abs(on_one[k]) + 1e-6) << k;
}

// What the comparisons read from a run file (rank 0).
struct RunFile {
  std::vector<double> particles, hits, impulse, moves;
  std::vector<double> mean_count, temperature;  // per cell, the last written step
};

RunFile read_run(const std::filesystem::path& path) {
  output::Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "open " + path.string());
  const auto series = [&](const std::string& name) { return output::Series::open(file.get(), name).read_all(); };
  RunFile run{series("/tracker/particles"),
              series("/tracker/objects/hits"),
              series("/tracker/objects/impulse"),
              series("/tracker/moves"),
              {},
              {}};
  std::vector<double> steps = series("/tracker/step");
  char last[24];
  std::snprintf(last, sizeof last, "%06llu", static_cast<unsigned long long>(steps.back()));
  // A box's fields are (nz, ny, nx): read flat, x fastest.
  run.mean_count = output::read_array(file.get(), std::string("/fields/tracker/") + last + "/mean_count");
  run.temperature = output::read_array(file.get(), std::string("/fields/tracker/") + last + "/temperature");
  return run;
}

double column(const RunFile& run, int k) { return run.moves[run.moves.size() - 11 + static_cast<std::size_t>(k)]; }
constexpr int kRemoved = 7, kLost = 8;

struct OneAndTwo {
  program::RunSummary one, two;
  RunFile one_file, two_file;
};

// The scene on both ranks (rank 0 writes), then on rank 0 alone; the files are read on rank 0.
OneAndTwo run_on_one_and_two(const scene::Scene& scene, const std::string& name) {
  const auto dir = std::filesystem::path(::testing::TempDir());
  OneAndTwo r;
  r.two = program::run_tracker(scene, dir / (name + "-two.h5"), Ranks(MPI_COMM_WORLD));
  if (rank() == 0) {
    r.one = program::run_tracker(scene, dir / (name + "-one.h5"), Ranks(MPI_COMM_SELF));
    r.one_file = read_run(dir / (name + "-one.h5"));
    r.two_file = read_run(dir / (name + "-two.h5"));
  }
  MPI_Barrier(MPI_COMM_WORLD);
  return r;
}

// |a - b| within `sigmas` standard deviations of the difference of two independent runs
// each with variance `variance`.
void expect_close(double a, double b, double variance, const char* what, double sigmas = 5.0) {
  const double tolerance = sigmas * std::sqrt(2.0 * variance);
  std::printf("  %-34s 1 rank %14.6g  2 ranks %14.6g  |diff| %10.4g  tolerance %10.4g\n", what, a, b, std::abs(a - b),
              tolerance);
  EXPECT_LE(std::abs(a - b), tolerance) << what;
}

constexpr double kBoltzmann = 1.380649e-23;

// SPARTA's collide deck in small: VSS argon at 273 K in a closed specular box of 10^3
// cells, 20 simulators per cell, around a diffuse ball at the gas's temperature.
TEST(TwoRanks, ClosedBoxConservesParticlesAndMatchesOneRank) {
  const scene::Scene scene = scene::load_scene_from_string(
      "time: {end: 3.5e-7}\ncoupling: {window: 3.5e-7}\noutput: {fields_every: 10}\n"
      "domain: {min: [0, 0, 0], max: [1.0e-4, 1.0e-4, 1.0e-4]}\neffects: [rarefied_gas]\n"
      "participants:\n  tracker:\n    dt: 7.0e-9\n    options:\n"
      "      mesh: {type: box, cells: [10, 10, 10]}\n"
      "      boundaries: {default: {kind: specular}}\n"
      "      collisions: {species: Ar, model: vss}\n"
      "      obstacles:\n"
      "        - {name: ball, shape: {ball: {centre: [5.0e-5, 5.0e-5, 5.0e-5], radius: 2.0e-5}}, "
      "wall: {kind: diffuse, temperature: 273.15}}\n"
      "      particles: {per_cell: 20, temperature: 273.15, mass: 6.63e-26, weight: 3.5e6, seed: 3}\n",
      "closed.yaml");
  const OneAndTwo r = run_on_one_and_two(scene, "closed");
  EXPECT_GT(r.two.migrated, 1000u);
  EXPECT_EQ(r.two.remaining, r.two.seeded);
  EXPECT_EQ(r.two.moves.lost, 0);
  if (rank() != 0) return;
  std::printf("closed box, VSS argon, diffuse ball, 50 steps; %zu particles moved between the ranks\n", r.two.migrated);
  for (double n : r.two_file.particles) EXPECT_EQ(n, static_cast<double>(r.two.seeded));  // every written step
  EXPECT_EQ(column(r.two_file, kLost), 0);
  EXPECT_EQ(column(r.two_file, kRemoved), 0);

  EXPECT_EQ(r.one.seeded, r.two.seeded);  // the same particles (Seeding.TwoRanksSeedWhatOneRankSeeds)
  // Collisions and hits: counts of rare independent events, Poisson.
  const auto one_c = static_cast<double>(r.one.collisions), two_c = static_cast<double>(r.two.collisions);
  expect_close(one_c, two_c, 0.5 * (one_c + two_c), "collisions");
  const double one_h = r.one_file.hits.back(), two_h = r.two_file.hits.back();
  expect_close(one_h, two_h, 0.5 * (one_h + two_h), "hits on the ball");
  // Simulators in the cells x < L/2 (cells x fastest): binomial with p = 1/2, the time
  // average only narrows it.
  const auto left = [](const std::vector<double>& mean_count) {
    double n = 0;
    for (std::size_t c = 0; c < mean_count.size(); ++c)
      if (c % 10 < 5) n += mean_count[c];
    return n;
  };
  const auto n = static_cast<double>(r.one.seeded);
  expect_close(left(r.one_file.mean_count), left(r.two_file.mean_count), n / 4, "mean simulators in x < L/2");
  // The gas's temperature (cells weighted by their simulators): a sample of N Maxwellian
  // simulators has a relative variance 2 / (3 N) of its kinetic energy.
  const auto temperature = [](const RunFile& f) {
    double sum = 0, weight = 0;
    for (std::size_t c = 0; c < f.mean_count.size(); ++c) {
      sum += f.mean_count[c] * f.temperature[c];
      weight += f.mean_count[c];
    }
    return sum / weight;
  };
  const double t1 = temperature(r.one_file);
  expect_close(t1, temperature(r.two_file), 2.0 / (3.0 * n) * t1 * t1, "temperature (K)");
}

scene::Scene sphere_stream(const std::string& end, const std::string& window) {
  std::ifstream in(std::filesystem::path(COSIM_CONFIGS_DIR) / "tracker-sphere-stream.yaml");
  std::stringstream text;
  text << in.rdbuf();
  std::string s = std::regex_replace(text.str(), std::regex(R"(time:\n  end: [^\n]+)"), "time:\n  end: " + end);
  s = std::regex_replace(s, std::regex(R"(coupling:\n  window: [^\n]+)"), "coupling:\n  window: " + window);
  return scene::load_scene_from_string(s, "tracker-sphere-stream.yaml");
}

// configs/tracker-sphere-stream.yaml for 2 ms: the stream half across the box, collisions,
// the diffuse sphere hit.
TEST(TwoRanks, SphereStreamMatchesOneRank) {
  const OneAndTwo r = run_on_one_and_two(sphere_stream("2.0e-3", "2.0e-3"), "stream");
  EXPECT_EQ(r.two.moves.lost, 0);
  EXPECT_EQ(r.two.remaining + static_cast<std::size_t>(r.two.moves.removed), r.two.seeded + r.two.injected);
  if (rank() != 0) return;
  std::printf("sphere stream, 200 steps; %zu particles moved between the ranks\n", r.two.migrated);
  EXPECT_EQ(column(r.one_file, kLost), 0);
  EXPECT_EQ(column(r.two_file, kLost), 0);
  // Counts of independent arrivals (the open box holds an ideal gas): Poisson.
  for (const auto& [one, two, what] :
       {std::tuple{static_cast<double>(r.one.injected), static_cast<double>(r.two.injected), "entered"},
        std::tuple{static_cast<double>(r.one.remaining), static_cast<double>(r.two.remaining), "particles at the end"},
        std::tuple{static_cast<double>(r.one.collisions), static_cast<double>(r.two.collisions), "collisions"},
        std::tuple{r.one_file.hits.back(), r.two_file.hits.back(), "hits on the sphere"}})
    expect_close(one, two, 0.5 * (one + two), what);
  // The drag's impulse (per unit mass) is a sum over H hits of each hit's dv_x, so its
  // variance is H <dv_x^2> = H ((I / H)^2 + var dv_x); var dv_x is at most the incoming
  // stream's thermal kT/m plus the diffuse re-emission's, under 2 (1 + pi/2) kT/m from
  // the spread of the sphere's normals: 4 kT/m bounds the sum, at 300 K.
  const double hits = 0.5 * (r.one_file.hits.back() + r.two_file.hits.back());
  const double impulse = r.one_file.impulse[r.one_file.impulse.size() - 3];
  const double per_hit = impulse / hits;
  expect_close(impulse, r.two_file.impulse[r.two_file.impulse.size() - 3],
               hits * (per_hit * per_hit + 4.0 * kBoltzmann * 300 / 6.63e-26), "drag impulse x (m/s)");
}

// The coupled mode's calls on two ranks through participant::run_on_ranks, as cosim-tracker
// makes them: a window repeated after restore() (state gathered from and scattered to both
// ranks) gives the same forces bit for bit.
TEST(TwoRanks, RepeatedWindowAfterRestoreGivesTheSameForces) {
  program::TrackerSolver solver{Ranks(MPI_COMM_WORLD)};
  const scene::Scene scene = sphere_stream("2.0e-3", "1.0e-3");
  participant::run_on_ranks(solver, MPI_COMM_WORLD, [&](participant::Solver& lead) {
    lead.initialise(scene, "tracker", {}, {});
    lead.advance({0, 1, 0.0, 1.0e-3}, {});
    const std::vector<double> state = lead.state();
    EXPECT_EQ(state.front(), 2);  // ranks: participant/mpi_team.hpp's layout
    const std::vector<double> first = participant::values_of(lead.advance({1, 1, 1.0e-3, 2.0e-3}, {}).forces);
    lead.restore(state);
    const std::vector<double> again = participant::values_of(lead.advance({1, 2, 1.0e-3, 2.0e-3}, {}).forces);
    EXPECT_EQ(first, again);
    // The stream's front reaches the sphere after 1.6 ms: the drag has begun.
    EXPECT_GT(first.at(0), 0.0);
    return 0;
  });
}

// A diffuse ball driven through gas at rest at four times its most probable speed, in a
// periodic box: the wall overruns particles and puts them back at its surface, often in the
// other rank's cells, which the next step's single migration sends there. Nothing is lost,
// every particle is kept, and a window repeated after restore() (particles in the other
// rank's cells included) gives the same forces bit for bit. The frame put together from
// the ranks' bricks of the periodic box then counts every particle once, and the mean
// simulators per cell add up to the gas's.
TEST(TwoRanks, AMovingBallOverrunsParticlesIntoTheOtherRanksCells) {
  const scene::Scene scene = scene::load_scene_from_string(R"(
time: {end: 1.0}
coupling: {window: 0.25}
domain: {min: [-4, -2.5, -2.5], max: [4, 2.5, 2.5]}
effects: [rarefied_gas]
bodies:
  - {name: ball, shape: {type: sphere, radius: 0.8}, fixed: true, position: [-2, 0, 0]}
participants:
  tracker:
    dt: 0.05
    options:
      mesh: {type: box, cells: [16, 10, 10], periodic: [true, true, true]}
      obstacles:
        - {name: ball, body: ball, wall: {kind: diffuse, temperature: 1}}
      particles: {per_cell: 10, temperature: 1, mass: 2.761298e-23, seed: 3}
)",
                                                           "moving_ball.yaml");
  const double u = 4.0;
  const auto inputs = [&](const participant::Window& w) {
    participant::Inputs in;
    for (auto [poses, t] : {std::pair{&in.poses_start, w.t0}, std::pair{&in.poses_end, w.t1}})
      *poses = {{{-2 + u * t, 0, 0}, Eigen::Quaterniond::Identity(), {u, 0, 0}, Eigen::Vector3d::Zero()}};
    return in;
  };
  program::TrackerSolver solver{Ranks(MPI_COMM_WORLD)};
  double counted = 0.0, mean_counted = 0.0;  // over the frame's cells, on rank 0
  participant::run_on_ranks(solver, MPI_COMM_WORLD, [&](participant::Solver& lead) {
    lead.initialise(scene, "tracker", inputs({0, 1, 0.0, 0.25}).poses_start, {});
    const participant::Window first{0, 1, 0.0, 0.25}, second{1, 1, 0.25, 0.5};
    lead.advance(first, inputs(first));
    const std::vector<double> state = lead.state();
    const std::vector<double> forces = participant::values_of(lead.advance(second, inputs(second)).forces);
    lead.restore(state);
    EXPECT_EQ(participant::values_of(lead.advance({1, 2, 0.25, 0.5}, inputs(second)).forces), forces);
    EXPECT_LT(forces.at(0), 0.0);  // the gas holds the ball back
    const field::FieldFrame frame = lead.fields();
    for (const double n : frame.fields.at(0).values) counted += n;
    for (const double n : frame.fields.at(1).values) mean_counted += n;
    return 0;
  });
  const step::Simulation& gas = solver.gas();
  EXPECT_EQ(gas.particles(), gas.seeded());
  const auto seeded = static_cast<double>(gas.seeded());  // collective
  if (rank() == 0) {
    EXPECT_EQ(counted, seeded);
    EXPECT_NEAR(mean_counted, seeded, 1e-9 * seeded);
  }
  EXPECT_EQ(gas.moves().lost, 0);
  EXPECT_GT(gas.migrated(), 100u);
  EXPECT_GT(gas.tallies().at(0).overrun, 10);
}

// A closed box whose left half is mostly a wall block, with collisions: the partition by
// cells gives one rank far fewer particles. The first step's check re-partitions by
// particles, after which the loads are even; particles are kept and none lost; and ten
// steps from a state saved under the first partition repeat bit for bit (the state holds
// the owners).
TEST(TwoRanks, ParticleWeightedBalanceEvensTheLoads) {
  const scene::Scene scene = scene::load_scene_from_string(
      "time: {end: 7.0e-8}\ncoupling: {window: 7.0e-8}\n"
      "domain: {min: [0, 0, 0], max: [2.0e-4, 1.0e-4, 1.0e-4]}\neffects: [rarefied_gas]\n"
      "participants:\n  tracker:\n    dt: 7.0e-9\n    options:\n"
      "      mesh: {type: box, cells: [16, 6, 6]}\n"
      "      boundaries: {default: {kind: specular}}\n"
      "      collisions: {species: Ar, model: vss}\n"
      "      obstacles:\n"
      "        - {name: block, shape: {box: {centre: [0.5e-4, 0.5e-4, 0.5e-4], half_extents: [0.45e-4, 0.6e-4, "
      "0.6e-4]}}, wall: {kind: diffuse, temperature: 273.15}}\n"
      "      particles: {per_cell: 20, temperature: 273.15, mass: 6.63e-26, weight: 3.5e6, seed: 3}\n"
      "      balance: {every: 5, threshold: 1.2}\n",
      "balance.yaml");
  step::Simulation gas(program::read_tracker(scene, Ranks(MPI_COMM_WORLD)), Ranks(MPI_COMM_WORLD));
  const auto imbalance = [&] {
    std::vector<long long> held(2, 0);
    held[static_cast<std::size_t>(rank())] = static_cast<long long>(gas.swarm().size());
    gas.decomposition().ranks().sum(held);
    return static_cast<double>(std::max(held[0], held[1])) / (0.5 * static_cast<double>(held[0] + held[1]));
  };
  const double before = imbalance();
  ASSERT_GT(before, 1.3) << "the cells' partition should load the ranks unevenly here";
  const std::vector<double> start = gas.state();
  gas.reseed(1);
  for (int k = 0; k < 10; ++k) gas.step(7.0e-9);
  const double after = imbalance();
  std::printf("balance: max/mean %.3f with the cells' partition, %.3f after %llu re-partition(s)\n", before, after,
              static_cast<unsigned long long>(gas.rebalances()));
  EXPECT_GE(gas.rebalances(), 1u);
  EXPECT_LT(after, 1.1);
  EXPECT_EQ(gas.particles(), gas.seeded());
  EXPECT_EQ(gas.moves().lost, 0);
  EXPECT_GT(gas.collisions(), 100);
  const std::vector<double> end = gas.state();
  gas.restore(start);
  gas.reseed(1);
  for (int k = 0; k < 10; ++k) gas.step(7.0e-9);
  EXPECT_TRUE(gas.state() == end) << "ten steps after restore() differ";

  // One particle: max/mean is 2 whatever the partition, so none is taken.
  std::string alone = scene.text;
  alone.replace(alone.find("per_cell: 20"), 12, "total: 1");
  step::Simulation one(program::read_tracker(scene::load_scene_from_string(alone, "alone.yaml"), Ranks(MPI_COMM_WORLD)),
                       Ranks(MPI_COMM_WORLD));
  for (int k = 0; k < 30; ++k) one.step(7.0e-9);
  EXPECT_EQ(one.rebalances(), 0u);
  EXPECT_EQ(one.particles(), 1u);
}

// A gas that draws no random numbers after seeding (specular walls and ball, a permeable
// zone, no collisions): two ranks move the very particles one rank does.
scene::Scene deterministic_gas(const std::string& fraction, const std::string& mesh = "{type: box, cells: [6, 6, 6]}") {
  return scene::load_scene_from_string(
      "time: {end: 0.4}\ncoupling: {window: 0.1}\noutput: {fields_every: 2}\n"
      "domain: {min: [0, 0, 0], max: [1, 1, 1]}\neffects: [rarefied_gas]\n"
      "participants:\n  tracker:\n    dt: 0.01\n    options:\n"
      "      mesh: " +
          mesh +
          "\n"
          "      boundaries: {default: {kind: specular}}\n"
          "      obstacles:\n"
          "        - {name: ball, shape: {ball: {centre: [0.5, 0.5, 0.5], radius: 0.2}}}\n"
          "        - {name: zone, shape: {box: {centre: [0, 0.5, 0.5], half_extents: [0.25, 0.6, 0.6]}}, permeable: true}\n"
          "      particles: {per_cell: 10, temperature: 1, drift: [1, 0.5, 0], mass: 1.380649e-23, seed: 4}\n"
          "      particle_output: {every: 2, fraction: " +
          fraction + "}\n",
      "gas.yaml");
}

// The particles written, a quarter of them chosen by a hash of their positions, are the same
// set in the same order on two ranks as on one, with the same attributes.
TEST(TwoRanks, TheSameParticleSampleAsOneRank) {
  const OneAndTwo r = run_on_one_and_two(deterministic_gas("0.25"), "sample");
  EXPECT_GT(r.two.migrated, 100u);
  if (rank() != 0) return;
  const auto dir = std::filesystem::path(::testing::TempDir());
  output::Handle one(H5Fopen((dir / "sample-one.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "open one");
  output::Handle two(H5Fopen((dir / "sample-two.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "open two");
  for (const std::string step : {"000000", "000020", "000040"}) {  // windows 0, 2 and 4
    const std::string at = "/fields/tracker/" + step + "/";
    const std::vector<double> points = output::read_array(one.get(), at + "points/particles");
    const double n = r.one.seeded;
    EXPECT_NEAR(static_cast<double>(points.size() / 3), 0.25 * n, 5 * std::sqrt(n * 0.25 * 0.75)) << step;
    EXPECT_EQ(output::read_array(two.get(), at + "points/particles"), points) << step;
    for (const char* attribute : {"velocity", "cell", "state_ball", "inside_ball", "state_zone", "inside_zone"}) {
      const std::string name = at + "point_attributes/particles/" + attribute;
      EXPECT_EQ(output::read_array(two.get(), name), output::read_array(one.get(), name)) << name;
    }
  }
}

// Guards against: a rank's brick written to another place of the box. The deterministic
// gas has one rank's particles in every cell: the file written rank by rank holds one
// rank's fields, the counts exactly, the moments to their sums' rounding.
TEST(TwoRanks, TheFieldsWrittenRankByRankAreOneRanks) {
  const OneAndTwo r = run_on_one_and_two(deterministic_gas("0.1"), "fields");
  if (rank() != 0) return;
  const auto dir = std::filesystem::path(::testing::TempDir());
  output::Handle one(H5Fopen((dir / "fields-one.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "open one");
  output::Handle two(H5Fopen((dir / "fields-two.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "open two");
  for (const std::string step : {"000000", "000020", "000040"}) {
    for (const char* field : {"count", "mean_count", "density", "velocity", "temperature", "pressure"}) {
      const std::string name = "/fields/tracker/" + step + "/" + field;
      const std::vector<double> a = output::read_array(one.get(), name), b = output::read_array(two.get(), name);
      EXPECT_EQ(output::array_dims(two.get(), name), output::array_dims(one.get(), name)) << name;
      ASSERT_EQ(a.size(), b.size()) << name;
      double largest = 0.0;
      for (const double x : a) largest = std::max(largest, std::abs(x));
      EXPECT_GT(largest, 0.0) << name;
      for (std::size_t c = 0; c < a.size(); ++c) {
        if (std::string(field).ends_with("count"))
          EXPECT_EQ(b[c], a[c]) << name << " [" << c << "]";
        else
          EXPECT_NEAR(b[c], a[c], 1e-12 * largest) << name << " [" << c << "]";
      }
    }
  }
}

// Each rank tracks on its part of the mesh (its cells and two layers of ghosts), and the
// moves that cross into the other rank's cells are finished there within the step: the
// deterministic gas makes exactly one rank's moves, crossings and object events.
// A box is split into bricks and each rank builds only its part (rank 0 the whole too, for
// the output); a perturbed box, as any other mesh, is read whole, split by METIS and cut.
TEST(TwoRanks, EachRankTracksOnItsPartAndHandsMovesOver) {
  for (const bool box : {true, false}) {
    const scene::Scene scene =
        deterministic_gas("0.1", box ? "{type: box, cells: [6, 6, 6]}"
                                     : "{type: box, cells: [6, 6, 6], perturb: {fraction: 0.05, seed: 2}}");
    step::Simulation two(program::read_tracker(scene, Ranks(MPI_COMM_WORLD)), Ranks(MPI_COMM_WORLD));
    step::Simulation one(program::read_tracker(scene));
    const mesh::Mesh& part = two.tracked();
    const Index cells = one.tracked().cell_count();
    EXPECT_LT(part.cell_count(), cells);
    EXPECT_GT(part.ghosts, 0);
    EXPECT_EQ(two.decomposition().ranks().sum(static_cast<long long>(part.own_cells())), cells);
    EXPECT_EQ(static_cast<bool>(two.decomposition().owners().bricks()), box);
    two.advance(0.0, 0.2);
    one.advance(0.0, 0.2);
    const tracking::MoveTally a = one.moves(), b = two.moves();
    EXPECT_EQ(b.moves, a.moves);
    EXPECT_EQ(b.faces_crossed, a.faces_crossed);
    EXPECT_EQ(b.object_events, a.object_events);
    EXPECT_EQ(b.lost, 0);
    EXPECT_EQ(two.particles(), one.particles());
    EXPECT_GT(two.migrated(), 100u);
    const std::vector<double> counts = two.counts();  // rank 0's
    if (rank() == 0) {
      EXPECT_EQ(counts, one.counts());
    } else {
      EXPECT_TRUE(counts.empty());
    }
  }
}

// A permeable zone: a ball with a small ball cut out of it, the hole written first (so its
// primitive is numbered first).
struct HoledZone {
  Vec3 hole;
  double hole_radius;
  Vec3 centre;
  double radius;
  bool holds(const Vec3& x) const { return (x - centre).norm() < radius && (x - hole).norm() > hole_radius; }
};

// Where particle i's record (simulation_state.cpp: position, velocity, cell in the whole
// mesh, then its states) starts in the gas's state: found by its values, not by the layout
// of what comes before it.
std::size_t record_of(const std::vector<double>& state, const step::Simulation& gas, std::size_t i) {
  const tracking::Particle p = gas.swarm().particle(i);
  step::StateWriter key;
  key.put(p.x, p.v, gas.tracked().global_cell(p.cell));
  const std::vector<double> values = key.take();
  return static_cast<std::size_t>(std::search(state.begin(), state.end(), values.begin(), values.end()) -
                                  state.begin());
}

// A particle left in a ghost (a stray: put there by a recovery or a moving wall) migrates at
// the next step to the ghost's owner, which classifies it anew. A second-layer ghost's
// registration lacks the primitives of the cells beyond the part, so its bits number other
// primitives than the owner's: here each side of the cut has a zone whose hole lies wholly in
// the cell beyond the other rank's second layer, so that rank's registration of the
// second-layer ghost has the zone's ball alone (bit 0), the owner's has the hole (bit 0) and
// the ball (bit 1), and the holder's state for a particle in the ball reads on the owner as
// "in the hole, outside the ball": outside the zone. Each rank restores a state in which two
// of its particles sit in the other rank's cells, one cell beyond the cut (a first-layer
// ghost, every state bit set) and two cells beyond (second layer, the holder's own states
// there); the gas is at rest, so one step later each is on its cell's owner alone, at the
// same point, with the states one rank gives it.
TEST(TwoRanks, StraysInGhostsReachTheOwnerClassifiedAnew) {
  const std::array<HoledZone, 2> zones{HoledZone{{1.625, 0.375, 0.375}, 0.08, {1.3, 0.5, 0.5}, 0.25},
                                       HoledZone{{0.375, 0.375, 0.375}, 0.08, {0.7, 0.5, 0.5}, 0.25}};
  std::ostringstream text;
  text << "time: {end: 0.01}\ncoupling: {window: 0.01}\ndomain: {min: [0, 0, 0], max: [2, 1, 1]}\n"
          "effects: [rarefied_gas]\nparticipants:\n  tracker:\n    dt: 0.01\n    options:\n"
          "      mesh: {type: box, cells: [8, 4, 4]}\n      boundaries: {default: {kind: specular}}\n"
          "      obstacles:\n";
  const auto ball = [&](const Vec3& c, double r) {
    std::ostringstream s;
    s << "{ball: {centre: [" << c.x() << ", " << c.y() << ", " << c.z() << "], radius: " << r << "}}";
    return s.str();
  };
  for (std::size_t z = 0; z < zones.size(); ++z)
    text << "        - {name: zone" << z
         << ", permeable: true, shape: {intersection: [{complement: " << ball(zones[z].hole, zones[z].hole_radius)
         << "}, " << ball(zones[z].centre, zones[z].radius) << "]}}\n";
  text << "      particles: {per_cell: 1, temperature: 0, mass: 1.0e-26, seed: 1}\n";
  const scene::Scene scene = scene::load_scene_from_string(text.str(), "strays.yaml");
  const program::TrackerScene whole = program::read_tracker(scene);  // one rank's registration: the owners'
  step::Simulation gas(program::read_tracker(scene, Ranks(MPI_COMM_WORLD)), Ranks(MPI_COMM_WORLD));
  const mesh::Mesh& part = gas.tracked();
  const mesh::PartCells numbers(part);
  const auto cell_at = [&](const Vec3& x) {
    for (Index c = 0; c < whole.mesh->cell_count(); ++c)
      if (mesh::contains(*whole.mesh, c, x)) return c;
    return Index{-1};
  };
  const auto next_to_own = [&](Index ghost) {
    for (Index f = part.cell_faces[ghost]; f < part.cell_faces[ghost + 1]; ++f)
      if (const Index n = part.faces[f].neighbour; n >= 0 && n < part.own_cells()) return true;
    return false;
  };

  // The bricks are cut at x = 1, the cells are 0.25 wide: each stray in a zone, well off its
  // surfaces.
  struct Stray {
    Vec3 x;
    bool second_layer;
    Index cell;                      // in the whole mesh
    std::vector<csg::State> states;  // one rank's
  };
  const auto stray = [&](const Vec3& x, bool second_layer) {
    Stray s{x, second_layer, cell_at(x), std::vector<csg::State>(zones.size())};
    whole.obstacles.classify(s.cell, x, s.states);
    return s;
  };
  const std::vector<Stray> strays{stray({1.2, 0.45, 0.45}, false), stray({1.375, 0.45, 0.45}, true),
                                  stray({0.8, 0.45, 0.45}, false), stray({0.625, 0.45, 0.45}, true)};
  std::vector<double> state = gas.state();
  std::size_t held = 0;
  for (const Stray& s : strays) {
    if (gas.decomposition().owns(s.cell)) continue;
    const Index ghost = numbers.local(s.cell);
    ASSERT_GE(ghost, part.own_cells());
    EXPECT_EQ(next_to_own(ghost), !s.second_layer);
    std::vector<csg::State> states(zones.size());
    gas.setup().obstacles.classify(ghost, s.x, states);
    if (s.second_layer) {
      EXPECT_NE(states, s.states) << "the hole beyond the part should number the ghost's bits unlike the owner's";
    } else {
      EXPECT_EQ(states, s.states) << "a first-layer ghost is registered as its owner registers it";
      states.assign(zones.size(), ~csg::State{0});
    }
    const std::size_t at = record_of(state, gas, held++);
    ASSERT_LT(at, state.size());
    step::StateWriter record;
    record.put(s.x, Vec3::Zero(), s.cell);
    for (const csg::State bits : states) record.put_bits(bits);
    const std::vector<double> values = record.take();
    std::copy(values.begin(), values.end(), state.begin() + static_cast<std::ptrdiff_t>(at));
  }
  EXPECT_EQ(held, 2u);
  gas.restore(state);
  gas.step(0.01);

  EXPECT_EQ(gas.particles(), gas.seeded());
  EXPECT_EQ(gas.migrated(), strays.size());  // the strays alone: the gas is at rest
  std::vector<long long> found(strays.size(), 0);
  for (std::size_t i = 0; i < gas.swarm().size(); ++i) {
    const tracking::Particle p = gas.swarm().particle(i);
    for (std::size_t k = 0; k < strays.size(); ++k) {
      const Stray& s = strays[k];
      if (p.x != s.x) continue;
      ++found[k];
      EXPECT_TRUE(gas.decomposition().owns(s.cell)) << "stray " << k;
      EXPECT_LT(p.cell, part.own_cells()) << "stray " << k;
      EXPECT_EQ(part.global_cell(p.cell), s.cell) << "stray " << k;
      const std::span<const csg::State> states = gas.swarm().states(i);
      EXPECT_EQ(std::vector<csg::State>(states.begin(), states.end()), s.states) << "stray " << k;
      for (std::size_t z = 0; z < zones.size(); ++z)
        EXPECT_EQ(gas.setup().obstacles.cells(static_cast<int>(z)).tree(p.cell).evaluate(states[z]),
                  zones[z].holds(s.x))
            << "stray " << k << " in zone " << z;
    }
  }
  gas.decomposition().ranks().sum(found);
  EXPECT_EQ(found, std::vector<long long>(strays.size(), 1));
}

// A fault that only one rank's part shows (70 primitives near rank 0's first cell, more than
// a logical state holds) stops both ranks with the scene error: none waits for the other.
TEST(TwoRanks, AFaultOnOneRanksPartStopsEveryRank) {
  const std::string balls =
      "{ball: {centre: [0.0200, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0215, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0230, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0245, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0260, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0275, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0290, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0305, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0320, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0335, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0350, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0365, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0380, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0395, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0410, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0425, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0440, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0455, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0470, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0485, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0500, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0515, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0530, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0545, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0560, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0575, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0590, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0605, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0620, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0635, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0650, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0665, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0680, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0695, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0710, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0725, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0740, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0755, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0770, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0785, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0800, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0815, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0830, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0845, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0860, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0875, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0890, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0905, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0920, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0935, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0950, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0965, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0980, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.0995, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.1010, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.1025, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.1040, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.1055, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.1070, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.1085, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.1100, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.1115, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.1130, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.1145, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.1160, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.1175, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.1190, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.1205, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.1220, 0.05, 0.05], radius: 0.01}}, {ball: {centre: [0.1235, 0.05, 0.05], radius: 0.01}}";
  const scene::Scene scene = scene::load_scene_from_string(
      "time: {end: 0.1}\ncoupling: {window: 0.1}\ndomain: {min: [0, 0, 0], max: [1, 1, 1]}\n"
      "effects: [rarefied_gas]\nparticipants:\n  tracker:\n    dt: 0.01\n    options:\n"
      "      mesh: {type: box, cells: [8, 4, 4]}\n      boundaries: {default: {kind: specular}}\n"
      "      obstacles:\n        - {name: grains, shape: {union: [" +
          balls +
          "]}}\n"
          "      particles: {per_cell: 1, temperature: 1, mass: 1.0e-26, seed: 1}\n",
      "fault.yaml");
  std::string message;
  try {
    step::Simulation gas(program::read_tracker(scene, Ranks(MPI_COMM_WORLD)), Ranks(MPI_COMM_WORLD));
  } catch (const scene::SceneError& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("obstacles"), std::string::npos) << "rank " << rank() << ": " << message;
  if (rank() == 0) {
    EXPECT_NE(message.find("primitives"), std::string::npos) << message;
  }
}

// Guards against: a stray (a particle a moving wall or a recovery left in a ghost) missing
// from the fields written rank by rank. Each rank restores a state in which one of its
// particles sits in the other rank's cells, and its sampler holds 5 simulators sampled
// there; the owner's brick counts the particle and averages the 5 in.
TEST(TwoRanks, ABrickCountsTheStraysTheOtherRankHolds) {
  const scene::Scene scene = scene::load_scene_from_string(
      "time: {end: 0.01}\ncoupling: {window: 0.01}\ndomain: {min: [0, 0, 0], max: [2, 1, 1]}\n"
      "effects: [rarefied_gas]\nparticipants:\n  tracker:\n    dt: 0.01\n    options:\n"
      "      mesh: {type: box, cells: [8, 4, 4]}\n      boundaries: {default: {kind: specular}}\n"
      "      particles: {per_cell: 3, temperature: 0, mass: 1.0e-26, seed: 1}\n",
      "strays.yaml");
  step::Simulation gas(program::read_tracker(scene, Ranks(MPI_COMM_WORLD)), Ranks(MPI_COMM_WORLD));
  // The bricks are cut at x = 1: the stray goes a cell beyond it, into hexahedron (4, 1, 1)
  // from rank 0 and (3, 1, 1) from rank 1.
  const Vec3 x{rank() == 0 ? 1.1 : 0.9, 0.4, 0.4};
  const std::array<int, 3> hex{rank() == 0 ? 4 : 3, 1, 1};
  const Index cell = mesh::box_cell_index({hex}, {8, 4, 4}, 1);
  ASSERT_FALSE(gas.decomposition().owns(cell));
  std::vector<double> state = gas.state();
  const std::size_t at = record_of(state, gas, 0);
  ASSERT_LT(at, state.size());
  step::StateWriter record;
  record.put(x, Vec3::Zero(), cell);
  const std::vector<double> values = record.take();
  std::copy(values.begin(), values.end(), state.begin() + static_cast<std::ptrdiff_t>(at));
  // The state ends with the sampler's sums: the sample count, then 16 a cell of the part.
  const auto sums_of = [&](Index local) {
    const std::size_t cells = static_cast<std::size_t>(gas.tracked().cell_count());
    return state.size() - 16 * cells + 16 * static_cast<std::size_t>(local);
  };
  const mesh::PartCells numbers(gas.tracked());
  state[sums_of(numbers.local(cell))] += 5.0;
  const Index strays_cell = mesh::box_cell_index({{rank() == 0 ? 3 : 4, 1, 1}}, {8, 4, 4}, 1);
  const double samples = state[sums_of(0) - 1], sampled_here = state[sums_of(numbers.local(strays_cell))];
  gas.restore(state);

  const step::Simulation::BrickSamples mine = gas.take_brick();
  const double counted = std::accumulate(mine.count.begin(), mine.count.end(), 0.0);
  std::vector<double> total{counted};
  gas.decomposition().ranks().sum(total);
  EXPECT_EQ(total[0], static_cast<double>(gas.particles()));
  // The other rank's stray lies in this rank's hexahedron across the cut.
  const std::array<int, 3> strays_hex{rank() == 0 ? 3 : 4, 1, 1};
  const std::array<int, 3>&lo = mine.brick.lo, &hi = mine.brick.hi;
  ASSERT_TRUE(mine.brick.holds(strays_hex));
  const auto in_brick = static_cast<std::size_t>(
      strays_hex[0] - lo[0] + (hi[0] - lo[0]) * (strays_hex[1] - lo[1] + (hi[1] - lo[1]) * (strays_hex[2] - lo[2])));
  double own = 0;  // this rank's particles in that cell, the restored stray not among them
  for (std::size_t i = 0; i < gas.swarm().size(); ++i)
    own += gas.tracked().global_cell(gas.swarm().cell(i)) == mesh::box_cell_index({strays_hex}, {8, 4, 4}, 1) ? 1 : 0;
  EXPECT_EQ(mine.count.at(in_brick), own + 1);
  EXPECT_EQ(mine.moments.at(in_brick).count, (sampled_here + 5.0) / samples);
}

// Coupled, the frame of rank 0 carries every rank's particles, at the windows the option names.
TEST(TwoRanks, TheCoupledFrameCarriesEveryRanksParticles) {
  program::TrackerSolver solver{Ranks(MPI_COMM_WORLD)};
  const scene::Scene scene = deterministic_gas("1");
  step::Simulation one(program::read_tracker(scene));  // rank 0's, for its counts
  participant::run_on_ranks(solver, MPI_COMM_WORLD, [&](participant::Solver& lead) {
    lead.initialise(scene, "tracker", {}, {});
    for (std::uint64_t k = 0; k <= 2; ++k) {
      if (k > 0) {
        lead.advance({k - 1, 1, 0.1 * double(k - 1), 0.1 * double(k)}, {});
        one.advance(0.1 * double(k - 1), 0.1 * double(k));
      }
      const field::FieldFrame frame = lead.fields();
      if (k == 1) {
        EXPECT_TRUE(frame.point_sets.empty());  // not a multiple of every: 2
        continue;
      }
      EXPECT_EQ(frame.fields[0].name, "count");
      const std::vector<double>& count = frame.fields[0].values;
      EXPECT_EQ(count, one.counts()) << "window " << k;  // the ranks' bricks where one rank has the cells
      EXPECT_EQ(frame.point_sets.size(), 1u) << "window " << k;
      if (frame.point_sets.size() == 1) {
        EXPECT_EQ(static_cast<double>(frame.point_sets[0].points.size() / 3),
                  std::accumulate(count.begin(), count.end(), 0.0))
            << "window " << k;
      }
    }
    return 0;
  });
}

}  // namespace
}  // namespace cosim::tracker::parallel
