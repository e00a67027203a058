// cosim-tracker --standalone with particle_output: the particles written with the fields at
// the steps it names, each with its velocity, cell and logical states, as many as
// /tracker/particles says and where the cells' counts say; a fraction writes a sample of
// those very particles, another seed another sample; and the sidecar shows them.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>

#include "coupler/output/h5_groups.hpp"
#include "coupler/output/h5_handle.hpp"
#include "coupler/output/h5_values.hpp"
#include "coupler/output/series.hpp"
#include "tracker/program/scene_tracker.hpp"
#include "tracker/program/standalone.hpp"
#include "tests/integration/xdmf_check.hpp"

namespace cosim::tracker::program {
namespace {

// The unit box of 8 x 4 x 4 cells, 10 windows of 10 steps, fields every window; mass = k_B,
// so the thermal speed is 1 m/s. A specular ball (a wall) and a permeable zone, the box's
// left half: its one surface inside is the plane x = 0.5, which the cells of the two
// outermost columns on either side do not see (their states for it are not looked at).
scene::Scene closed_box(const std::string& particle_output) {
  return scene::load_scene_from_string(
      "time: {end: 1.0}\ncoupling: {window: 0.1}\noutput: {fields_every: 1}\n"
      "domain: {min: [0, 0, 0], max: [1, 1, 1]}\neffects: [rarefied_gas]\n"
      "participants:\n  tracker:\n    dt: 0.01\n    options:\n"
      "      mesh: {type: box, cells: [8, 4, 4]}\n"
      "      boundaries: {default: {kind: diffuse, temperature: 1}}\n"
      "      obstacles:\n"
      "        - {name: ball, shape: {ball: {centre: [0.75, 0.5, 0.5], radius: 0.15}}}\n"
      "        - {name: left, shape: {box: {centre: [0, 0.5, 0.5], half_extents: [0.5, 0.6, 0.6]}}, permeable: true}\n"
      "      particles: {per_cell: 20, temperature: 1, drift: [0.5, 0, 0], mass: 1.380649e-23, seed: 7}\n"
      "      particle_output: " +
          particle_output + "\n",
      "scene.yaml");
}

const std::array<const char*, 6> kAttributes{"velocity",    "cell",       "state_ball",
                                             "inside_ball", "state_left", "inside_left"};

// The particles of one written step, as the file holds them.
struct Dump {
  std::string step;
  double particles = 0;       // /tracker/particles of the step
  std::vector<double> count;  // the step's cell field
  std::vector<double> points;
  std::array<std::vector<double>, kAttributes.size()> attributes;  // as kAttributes
  std::size_t size() const { return points.size() / 3; }
  const std::vector<double>& operator[](const char* name) const {
    return attributes[static_cast<std::size_t>(
        std::find_if(kAttributes.begin(), kAttributes.end(), [&](const char* a) { return std::string(a) == name; }) -
        kAttributes.begin())];
  }
};

std::vector<Dump> read_dumps(const std::filesystem::path& path) {
  output::Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "open " + path.string());
  const std::vector<double> steps = output::Series::open(file.get(), "/tracker/step").read_all();
  const std::vector<double> particles = output::Series::open(file.get(), "/tracker/particles").read_all();
  std::vector<Dump> dumps;
  output::Handle fields = output::open_group(file.get(), "/fields/tracker");
  for (const std::string& step : output::link_names(fields.get())) {
    if (step == "grid") continue;
    output::Handle group = output::open_group(fields.get(), step);
    if (!output::has_link(group.get(), "points")) continue;
    Dump d{step, 0, output::read_array(group.get(), "count"), output::read_array(group.get(), "points/particles"), {}};
    d.particles =
        particles[static_cast<std::size_t>(std::find(steps.begin(), steps.end(), std::stod(step)) - steps.begin())];
    for (std::size_t a = 0; a < kAttributes.size(); ++a) {
      const std::string name = std::string("point_attributes/particles/") + kAttributes[a];
      d.attributes[a] = output::read_array(group.get(), name);
      EXPECT_EQ(output::integer_array(group.get(), name), a > 0) << name;  // all but the velocity
    }
    dumps.push_back(std::move(d));
  }
  return dumps;
}

std::filesystem::path out(const char* name) { return std::filesystem::path(::testing::TempDir()) / name; }

csg::State state_of(const std::vector<double>& halves, std::size_t i) {
  return static_cast<csg::State>(halves[2 * i]) << 32 | static_cast<csg::State>(halves[2 * i + 1]);
}

TEST(ParticleOutput, EveryParticleWithItsVelocityCellAndStatesAtTheStepsItNames) {
  const scene::Scene scene = closed_box("{every: 5}");
  run_tracker(scene, out("particles.h5"));
  const std::vector<Dump> dumps = read_dumps(out("particles.h5"));
  ASSERT_EQ(dumps.size(), 3u);  // windows 0, 5 and 10 of the 11 field writes
  EXPECT_EQ(dumps[0].step, "000000");
  EXPECT_EQ(dumps[1].step, "000050");
  EXPECT_EQ(dumps[2].step, "000100");

  const TrackerScene t = read_tracker(scene);  // the mesh and the obstacles, as the run had them
  for (const Dump& d : dumps) {
    ASSERT_EQ(static_cast<double>(d.size()), d.particles) << d.step;
    EXPECT_GT(d.size(), 2400u);  // 2560 drawn, those inside the ball dropped
    for (std::size_t a = 0; a < kAttributes.size(); ++a)
      EXPECT_EQ(d.attributes[a].size(), d.size() * (a == 0 ? 3 : a % 2 == 0 ? 2 : 1)) << kAttributes[a];
    std::vector<double> count(d.count.size(), 0.0);
    double vx = 0;
    for (std::size_t i = 0; i < d.size(); ++i) {
      const Vec3 x(d.points[3 * i], d.points[3 * i + 1], d.points[3 * i + 2]);
      const auto cell = static_cast<Index>(d["cell"][i]);
      count[static_cast<std::size_t>(cell)] += 1;
      vx += d["velocity"][3 * i] / static_cast<double>(d.size());
      if (i > 0) {
        EXPECT_LE(d["cell"][i - 1], d["cell"][i]);  // in cell order
      }
      EXPECT_FALSE(tracking::is_lost(*t.domain, {x, Vec3::Zero(), cell}))
          << d.step << " particle " << i;  // in its cell
      // The states are those of direct evaluation (the particles are not within round-off
      // of a surface), bit for bit: no bits a particle carried into a cell that does not
      // look at them.
      std::vector<csg::State> states(2);
      t.obstacles.classify(cell, x, states);
      EXPECT_EQ(state_of(d["state_ball"], i), states[0]) << d.step << " particle " << i;
      EXPECT_EQ(state_of(d["state_left"], i), states[1]) << d.step << " particle " << i;
      EXPECT_EQ(d["inside_ball"][i], 0.0);
      EXPECT_EQ(d["inside_left"][i], x.x() < 0.5 ? 1.0 : 0.0) << x.transpose();
    }
    EXPECT_EQ(count, d.count) << d.step;
    if (d.step == "000000") {
      EXPECT_NEAR(vx, 0.5, 0.1);  // the drift; 1 m/s thermal over 2500
    }
  }

  std::ifstream in(out("particles.xmf"));
  const testing::XdmfContents xdmf = testing::read_xdmf({std::istreambuf_iterator<char>(in), {}});
  ASSERT_EQ(xdmf.polyvertices.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    const testing::XdmfPolyvertex& p = xdmf.polyvertices[k];
    EXPECT_EQ(p.elements, dumps[k].size());
    EXPECT_EQ(p.points.dataset, "/fields/tracker/" + dumps[k].step + "/points/particles");
    ASSERT_EQ(p.attributes.size(), kAttributes.size());
    for (std::size_t a = 0; a < kAttributes.size(); ++a) {
      EXPECT_EQ(p.attributes[a].name, kAttributes[a]);
      EXPECT_EQ(p.attributes[a].number_type, a == 0 ? "Float" : "Int");
      EXPECT_EQ(p.attributes[a].item.dataset,
                "/fields/tracker/" + dumps[k].step + "/point_attributes/particles/" + kAttributes[a]);
    }
  }
}

// The particles' positions of every dump, as a set.
std::vector<std::set<std::array<double, 3>>> positions(const std::vector<Dump>& dumps) {
  std::vector<std::set<std::array<double, 3>>> out;
  for (const Dump& d : dumps) {
    out.emplace_back();
    for (std::size_t i = 0; i < d.size(); ++i)
      out.back().insert({d.points[3 * i], d.points[3 * i + 1], d.points[3 * i + 2]});
  }
  return out;
}

TEST(ParticleOutput, AFractionIsASampleOfTheSameParticlesAndTheSeedPicksIt) {
  run_tracker(closed_box("{every: 5}"), out("all.h5"));
  run_tracker(closed_box("{every: 5, fraction: 0.25}"), out("quarter.h5"));
  run_tracker(closed_box("{every: 5, fraction: 0.25, seed: 1}"), out("other.h5"));
  const std::vector<Dump> all = read_dumps(out("all.h5")), quarter = read_dumps(out("quarter.h5"));
  const auto everyone = positions(all), sample = positions(quarter), other = positions(read_dumps(out("other.h5")));
  ASSERT_EQ(sample.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    // Binomial: within 5 standard deviations of a quarter.
    const double n = all[k].particles;
    EXPECT_NEAR(static_cast<double>(quarter[k].size()), 0.25 * n, 5 * std::sqrt(n * 0.25 * 0.75)) << all[k].step;
    EXPECT_EQ(quarter[k].particles, n);  // the whole gas ran: only the output is a sample
    EXPECT_TRUE(std::includes(everyone[k].begin(), everyone[k].end(), sample[k].begin(), sample[k].end()));
    EXPECT_TRUE(std::includes(everyone[k].begin(), everyone[k].end(), other[k].begin(), other[k].end()));
    EXPECT_NE(sample[k], other[k]);
  }
}

}  // namespace
}  // namespace cosim::tracker::program
