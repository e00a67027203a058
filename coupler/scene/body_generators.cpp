#include "coupler/scene/body_generators.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <system_error>

#include "coupler/scene/extent.hpp"
#include "coupler/scene/names.hpp"
#include "coupler/scene/packing.hpp"
#include "coupler/scene/pose_file.hpp"
#include "coupler/scene/room.hpp"
#include "coupler/scene/sections.hpp"

namespace cosim::scene {
namespace {

namespace fs = std::filesystem;

// A guard against a slip of the pen (a spacing in millimetres read as metres) that would
// have one entry allocate billions of bodies.
constexpr std::size_t max_bodies = 10'000'000;

// Random addition gives up after this many refused draws in a row unless `attempts` says.
constexpr int default_attempts = 10'000;

// Widths and spacings that agree to this relative tolerance count as fitting: 0.0075 * 3
// must fit into 0.0225 although floating point disagrees in the last bit.
constexpr double fit = 1e-9;

constexpr std::array axis_names{"x", "y", "z"};

// A number, the same on every axis, or a list of 3.
Vec3 per_axis(const Reader& r, const std::string& key, const Range& range) {
  if (!r.has(key)) return {};
  if (r.node(key).IsSequence()) return r.vec3(key, range);
  const double v = r.number(key, range);
  return {v, v, v};
}

Uniform seeded(const Reader& r) {
  return Uniform(static_cast<std::uint64_t>(r.integer("seed", 0, Range::at_least(0))));
}

// The entry's `region`, which must lie inside the domain.
Domain read_region(const Reader& entry, const Domain& domain) {
  const Reader r = entry.map("region");
  const Domain region = read_box(r);
  const std::string where = fmt::format("outside the domain {} .. {}", text(domain.min), text(domain.max));
  for (int k = 0; k < 3; ++k) {
    if (region.min[k] < domain.min[k] - domain_slack) r.fail("min", where);
    if (region.max[k] > domain.max[k] + domain_slack) r.fail("max", where);
  }
  return region;
}

std::size_t capped(const Reader& r, const std::string& key, double n) {
  // NaN from a region and a body too small to have a volume in double precision (0 / 0).
  if (std::isnan(n))
    r.fail(key, "gives no number of bodies: the sizes of the region and the body are below double precision");
  if (n > static_cast<double>(max_bodies))
    r.fail(key, fmt::format("makes {:g} bodies; one entry makes at most {}", n, max_bodies));
  return static_cast<std::size_t>(n);
}

// Axis k of a lattice in [lo, hi] of bodies `extent` wide, each moved by up to `jitter`
// either way: `count` centres (0: as many as fit) `spacing` apart (0: spread over the
// region), the whole centred in the region.
LatticeAxis lattice_axis(const Reader& r, int k, double lo, double hi, double extent, double jitter, int count,
                         double spacing) {
  const char* axis = axis_names[static_cast<std::size_t>(k)];
  const double width = hi - lo;
  const double need = extent + 2 * jitter;  // a body's room, and the least spacing that keeps two apart
  const double room = width - need;         // for the centres' span
  if (room < -fit * width)
    r.fail("region", fmt::format("is {:g} wide on {}, less than a body and its jitter take ({:g})", width, axis, need));
  LatticeAxis a;
  if (count > 0 && spacing > 0) {
    if ((count - 1) * spacing > room + fit * width)
      r.fail("count", fmt::format("{} bodies {:g} apart on {} take {:g}, more than the region's {:g}", count, spacing,
                                  axis, (count - 1) * spacing + need, width));
    a = {count, 0.0, spacing};
  } else if (count > 0) {
    a = {count, 0.0, count > 1 ? room / (count - 1) : 0.0};
  } else {
    a = {static_cast<int>(capped(r, "spacing", std::floor(std::max(room, 0.0) / spacing + fit) + 1)), 0.0, spacing};
  }
  if (a.count > 1 && a.step < need * (1 - fit))
    r.fail(spacing > 0 ? "spacing" : "count",
           fmt::format("puts bodies {:g} apart on {}, closer than their width and twice the jitter ({:g}): they "
                       "could overlap",
                       a.step, axis, need));
  a.first = 0.5 * (lo + hi) - 0.5 * (a.count - 1) * a.step;
  return a;
}

std::vector<Vec3> lattice_centres(const Reader& r, const Body& common, const Domain& domain) {
  const Domain region = read_region(r, domain);
  std::array<int, 3> count{};
  Vec3 spacing{};
  const bool has_count = r.has("count"), has_spacing = r.has("spacing");
  if (!has_count && !has_spacing) r.fail("count", "missing: a lattice needs count, spacing or both");
  if (has_count) r.integers("count", count, Range::at_least(1));
  if (has_spacing) spacing = r.vec3("spacing", Range::above(0));
  const Vec3 jitter = per_axis(r, "jitter", Range::at_least(0));
  Uniform random = seeded(r);
  const Vec3 half = half_extent(common.shape, common.orientation);
  std::array<LatticeAxis, 3> axes;
  double total = 1;
  for (int k = 0; k < 3; ++k) {
    axes[k] = lattice_axis(r, k, region.min[k], region.max[k], 2 * half[k], jitter[k], count[k], spacing[k]);
    total *= axes[k].count;
  }
  capped(r, has_count ? "count" : "spacing", total);
  return lattice(axes, jitter, random);
}

// The region's volume within the containers among `earlier` (all of it without one),
// from the midpoints of a 64^3 lattice over it.
double free_volume(const Domain& region, std::span<const Body> earlier) {
  const double box =
      (region.max[0] - region.min[0]) * (region.max[1] - region.min[1]) * (region.max[2] - region.min[2]);
  if (std::none_of(earlier.begin(), earlier.end(), [](const Body& b) { return b.shape.container; })) return box;
  constexpr int n = 64;
  long inside = 0;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const std::array<int, 3> at{i, j, k};
        Vec3 x{};
        for (int d = 0; d < 3; ++d) x[d] = region.min[d] + (at[d] + 0.5) / n * (region.max[d] - region.min[d]);
        inside += room(earlier, x) > 0;
      }
  return box * static_cast<double>(inside) / (n * n * n);
}

std::vector<Vec3> random_centres(const Reader& r, const Body& common, const GeneratorContext& c) {
  const Domain region = read_region(r, c.domain);
  const Solid body = *solid_of(common.shape, common.orientation, {});
  Domain centres = region;  // where a centre keeps the whole body inside the region
  for (int k = 0; k < 3; ++k) {
    centres.min[k] += body.half[k];
    centres.max[k] -= body.half[k];
    if (centres.max[k] < centres.min[k])
      r.fail("region", fmt::format("is {:g} wide on {}, less than a body ({:g})", region.max[k] - region.min[k],
                                   axis_names[static_cast<std::size_t>(k)], 2 * body.half[k]));
  }
  const double region_volume = free_volume(region, c.earlier);
  const double body_volume = volume(common.shape);
  const bool has_count = r.has("count"), has_fraction = r.has("solid_fraction");
  if (has_count == has_fraction)
    r.fail(has_count ? "solid_fraction" : "count", has_count
                                                       ? "give count or solid_fraction, not both"
                                                       : "missing: random addition needs count or solid_fraction");
  const std::string key = has_count ? "count" : "solid_fraction";
  std::size_t count = 0;
  if (has_count) {
    count = capped(r, key, r.integer(key, Range::at_least(1)));
  } else {
    count = capped(r, key, std::round(r.number(key, Range::open(0, 1)) * region_volume / body_volume));
    if (count == 0) r.fail(key, "is less than one body in the region");
  }
  Uniform random = seeded(r);
  const int attempts = r.integer("attempts", default_attempts, Range::at_least(1));
  std::vector<Solid> obstacles;
  for (const Body& b : c.earlier)
    if (const auto s = solid_of(b)) obstacles.push_back(*s);
  const auto room_left = [&](const Vec3& x) { return room(c.earlier, x); };
  std::vector<Vec3> placed = random_addition(body, centres, count, obstacles, room_left, attempts, random);
  if (placed.size() < count)
    r.fail(key, fmt::format("random addition placed only {} of {} bodies (solid fraction {:.3g}); it stops when no "
                            "room is left or {} draws in a row are refused, and jams near 0.38 for spheres, lower "
                            "near walls and for other shapes (docs/scenes.md): ask for fewer, enlarge the region or "
                            "raise attempts",
                            placed.size(), count, static_cast<double>(placed.size()) * body_volume / region_volume,
                            attempts));
  return placed;
}

std::vector<Body> file_bodies(const Reader& r, const Body& common, const GeneratorContext& c) {
  const fs::path file = existing_file(r, c.dir);
  std::error_code error;
  if (fs::equivalent(file, c.output, error))
    r.fail("file", "is the scene's output.file, which a run of this scene overwrites before its participants read it");
  std::vector<Body> bodies;
  for (const FilePose& p : read_pose_file(r, file)) {
    Body b = common;
    b.position = p.position;
    if (p.orientation) b.orientation = *p.orientation;
    if (p.velocity) b.velocity = *p.velocity;
    if (const auto problem = outside_domain(b, c.domain)) r.fail("file", p.where + ": the body " + *problem);
    bodies.push_back(std::move(b));
  }
  return bodies;
}

std::vector<Body> placed_at(const Body& common, const std::vector<Vec3>& centres) {
  std::vector<Body> bodies(centres.size(), common);
  for (std::size_t i = 0; i < centres.size(); ++i) bodies[i].position = centres[i];
  return bodies;
}

// The name of body `index`: `pattern` formatted with it, as fmt (and C++20 std::format) do.
std::string name_at(const Reader& r, const std::string& pattern, std::size_t index) {
  std::string name;
  try {
    name = fmt::format(fmt::runtime(pattern), index);
  } catch (const fmt::format_error& e) {
    r.fail("name", fmt::format("not a name pattern ({}); write the index as {{}} or {{:03d}}", e.what()));
  }
  if (!is_name(name)) r.fail("name", fmt::format("makes '{}' for index {}: {}", name, index, name_rule));
  return name;
}

}  // namespace

Generated generate_bodies(const Reader& r, const GeneratorContext& c) {
  const auto kind = pick<Generator>(r, "generate", generator_names);
  const std::string pattern = r.string("name");
  const std::string first = name_at(r, pattern, 0);
  if (name_at(r, pattern, 1) == first)
    r.fail("name", "has no field for the index, so every body would get the same name; write it as {} or {:03d}");
  const Body common = read_common(r, c.dir);
  if (!bounded(common.shape))
    r.fail("shape", "generated bodies need a shape of known extent: give each plane or mesh an entry of its own");
  std::vector<Body> bodies;
  switch (kind) {
    case Generator::Lattice:
      bodies = placed_at(common, lattice_centres(r, common, c.domain));
      break;
    case Generator::Random:
      bodies = placed_at(common, random_centres(r, common, c));
      break;
    case Generator::File:
      bodies = file_bodies(r, common, c);
      break;
  }
  r.finish();
  for (std::size_t i = 0; i < bodies.size(); ++i) bodies[i].name = name_at(r, pattern, i);
  return {kind, std::move(bodies)};
}

}  // namespace cosim::scene
