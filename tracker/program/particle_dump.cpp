#include "tracker/program/particle_dump.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <numeric>

namespace cosim::tracker::program {
namespace {

// splitmix64's increment and finaliser (Steele, Lea & Flood 2014): each input bit flips
// about half of the output's, so nearby positions hash independently.
constexpr std::uint64_t kGolden = 0x9e3779b97f4a7c15u;
std::uint64_t mixed(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
  return z ^ (z >> 31);
}

// Whether the sample holds the particle at x: the hash of the seed and x's bits as a
// uniform number in [0, 1), below the fraction.
bool chosen(const Vec3& x, const ParticleOutput& output) {
  if (output.fraction >= 1.0) return true;
  std::uint64_t h = mixed(output.seed + kGolden);
  for (int k = 0; k < 3; ++k) h = mixed((h ^ std::bit_cast<std::uint64_t>(x[k])) + kGolden);
  return static_cast<double>(h >> 11) * 0x1p-53 < output.fraction;
}

// A chosen particle as it crosses the ranks: cell, x y z, vx vy vz, then per obstacle its
// state's high and low 32 bits and whether it is inside. The cell comes first so that
// records sort by it.
constexpr std::size_t kCell = 0, kX = 1, kV = 4, kObstacles = 7, kPerObstacle = 3;
// A record holds what the set will, which the work report counts (particle_values()).
static_assert(kObstacles + 2 * kPerObstacle == particle_values(2));

// The state over the cell's primitives alone: an obstacle without primitives in a cell
// never looks at its state there, which keeps whatever bits the particle brought in.
csg::State cell_state(const tracking::Obstacles& obstacles, int o, Index cell, csg::State state) {
  const std::size_t n = obstacles.cells(o).primitives(obstacles.bounding_cell(cell)).size();
  return n >= 64 ? state : state & ((csg::State{1} << n) - 1);
}

void add_record(std::vector<double>& records, const tracking::Obstacles& obstacles, const tracking::Particle& p,
                Index global_cell, std::span<const csg::State> states) {
  records.push_back(global_cell);
  records.insert(records.end(), p.x.data(), p.x.data() + 3);
  records.insert(records.end(), p.v.data(), p.v.data() + 3);
  for (int o = 0; o < obstacles.count(); ++o) {
    const csg::State s = cell_state(obstacles, o, p.cell, states[static_cast<std::size_t>(o)]);
    records.push_back(static_cast<double>(s >> 32));
    records.push_back(static_cast<double>(s & 0xffffffffu));
    records.push_back(obstacles.cells(o).tree(obstacles.bounding_cell(p.cell)).evaluate(s) ? 1.0 : 0.0);
  }
}

}  // namespace

field::PointSet particle_set(const step::Simulation& gas, const ParticleOutput& output) {
  const tracking::Swarm& swarm = gas.swarm();
  const tracking::Obstacles& obstacles = gas.setup().obstacles;
  const auto objects = static_cast<std::size_t>(obstacles.count());
  const std::size_t width = kObstacles + kPerObstacle * objects;
  std::vector<double> mine;
  for (std::size_t i = 0; i < swarm.size(); ++i)
    if (const tracking::Particle p = swarm.particle(i); chosen(p.x, output))
      add_record(mine, obstacles, p, gas.tracked().global_cell(p.cell), swarm.states(i));
  const std::vector<double> all = gas.decomposition().ranks().gather(mine);
  const std::size_t n = all.size() / width;
  const auto record = [&](std::size_t i) { return all.begin() + static_cast<std::ptrdiff_t>(i * width); };
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return std::lexicographical_compare(record(a), record(a + 1), record(b), record(b + 1));
  });

  field::PointSet set{kParticleSet, {}, {{"velocity", 3, {}}, {"cell", 1, {}, true}}};
  for (int o = 0; o < obstacles.count(); ++o) {
    const std::string& name = obstacles.object(o).name;
    set.attributes.push_back({state_attribute(name), 2, {}, true});
    set.attributes.push_back({inside_attribute(name), 1, {}, true});
  }
  set.points.reserve(3 * n);
  for (field::PointAttribute& a : set.attributes) a.values.reserve(static_cast<std::size_t>(a.components) * n);
  for (const std::size_t i : order) {
    const auto r = record(i);
    const auto append = [&](std::vector<double>& to, std::size_t from, std::size_t count) {
      to.insert(to.end(), r + static_cast<std::ptrdiff_t>(from), r + static_cast<std::ptrdiff_t>(from + count));
    };
    append(set.points, kX, 3);
    append(set.attributes[0].values, kV, 3);
    append(set.attributes[1].values, kCell, 1);
    for (std::size_t o = 0; o < objects; ++o) {
      const std::size_t at = kObstacles + kPerObstacle * o;
      append(set.attributes[2 + 2 * o].values, at, 2);
      append(set.attributes[3 + 2 * o].values, at + 2, 1);
    }
  }
  return set;
}

}  // namespace cosim::tracker::program
