#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "coupler/scene/body_generators.hpp"
#include "coupler/scene/cell_grid.hpp"
#include "coupler/scene/extent.hpp"
#include "coupler/scene/names.hpp"
#include "coupler/scene/room.hpp"
#include "coupler/scene/sections.hpp"

namespace cosim::scene {
namespace {

namespace fs = std::filesystem;

const Range positive = Range::above(0);

// Quaternions and normals are written by hand with a few digits; a tolerance lets
// [0.7071, 0, 0, 0.7071] through, and storing the exact unit vector keeps the solvers clean.
constexpr double unit_tolerance = 1e-6;

template <std::size_t N>
double norm(const std::array<double, N>& v) {
  double sum = 0;
  for (double x : v) sum += x * x;
  return std::sqrt(sum);
}

template <std::size_t N>
std::array<double, N> scaled(std::array<double, N> v, double factor) {
  for (double& x : v) x *= factor;
  return v;
}

Shape read_shape(const Reader& r, bool fixed, const fs::path& dir) {
  Shape s;
  s.type = pick<ShapeType>(r, "type", shape_names);
  switch (s.type) {
    case ShapeType::Sphere:
      s.radius = r.number("radius", positive);
      break;
    case ShapeType::Ellipsoid:
      s.radii = r.vec3("radii", positive);
      break;
    case ShapeType::Box:
      s.half_extents = r.vec3("half_extents", positive);
      break;
    case ShapeType::Cylinder:
    case ShapeType::Capsule:
      s.radius = r.number("radius", positive);
      s.height = r.number("height", positive);
      break;
    case ShapeType::Plane: {
      // An infinite body has no mass properties to integrate.
      if (!fixed) r.fail("type", "a plane must be a fixed body (add fixed: true)");
      const Vec3 normal = r.vec3("normal");
      if (norm(normal) == 0) r.fail("normal", "must not be zero");
      s.normal = scaled(normal, 1 / norm(normal));
      break;
    }
    case ShapeType::Mesh:
      s.file = existing_file(r, dir);
      break;
  }
  s.container = r.boolean("container", false);
  if (s.container && (s.type == ShapeType::Plane || s.type == ShapeType::Mesh))
    r.fail("container", "holds bodies in the inside of a sphere, ellipsoid, box, cylinder or capsule, not of a " +
                            std::string(s.type == ShapeType::Plane ? "plane" : "mesh"));
  if (s.container && !fixed) r.fail("container", "a container must be a fixed body (add fixed: true)");
  r.finish();
  return s;
}

// A fixed body never moves, so it needs no density.
Material read_material(const Reader& r, bool fixed) {
  Material m;
  m.density = fixed ? r.number("density", m.density, positive) : r.number("density", positive);
  m.restitution = r.number("restitution", m.restitution, Range::closed(0, 1));
  m.friction = r.number("friction", m.friction, Range::at_least(0));
  r.finish();
  return m;
}

Body read_single(const Reader& r, const Domain& domain, const fs::path& dir) {
  const std::string name = r.string("name");
  if (!is_name(name)) r.fail("name", name_rule);
  Body b = read_common(r, dir);
  b.name = name;
  b.position = r.vec3("position");
  r.finish();
  if (const auto problem = outside_domain(b, domain)) r.fail("position", fmt::format("body '{}' {}", b.name, *problem));
  return b;
}

// Sphere pairs are checked exactly, and every pair with a generated body in it by the
// bodies' bounds (solid.hpp), as random addition places them. Hand-written pairs of other
// shapes are left alone: their bounds are loose, and scenes stack them on purpose.
void check_overlaps(const std::vector<Reader>& items, const std::vector<Body>& bodies,
                    const std::vector<std::size_t>& entry_of, const std::vector<bool>& generated) {
  std::vector<Solid> solids;
  std::vector<std::size_t> body_of;  // solid -> body
  for (std::size_t i = 0; i < bodies.size(); ++i)
    if (const auto s = solid_of(bodies[i])) {
      solids.push_back(*s);
      body_of.push_back(i);
    }
  if (solids.size() < 2) return;
  // Cells as wide as the median body: bodies of one size meet only their neighbours, and
  // a few large ones are listed in many cells or kept aside (cell_grid.hpp).
  std::vector<double> diameters;
  for (const Solid& s : solids) diameters.push_back(2 * s.radius);
  std::nth_element(diameters.begin(), diameters.begin() + diameters.size() / 2, diameters.end());
  CellGrid grid(diameters[diameters.size() / 2]);
  const auto sphere = [&](std::size_t i) { return bodies[i].shape.type == ShapeType::Sphere; };
  for (std::size_t n = 0; n < solids.size(); ++n) {
    const std::size_t j = body_of[n];
    const auto checked = [&](std::size_t m) {
      const std::size_t i = body_of[m];
      return generated[i] || generated[j] || (sphere(i) && sphere(j));
    };
    if (const auto m = grid.first_overlap(solids[n], checked)) {
      const std::size_t i = body_of[*m];
      const Body &a = bodies[i], &b = bodies[j];
      const std::string problem =
          sphere(i) && sphere(j)
              ? fmt::format("body '{}' at {} overlaps body '{}' of bodies[{}] by {:g} m", b.name, text(b.position),
                            a.name, entry_of[i],
                            a.shape.radius + b.shape.radius -
                                std::hypot(a.position[0] - b.position[0], a.position[1] - b.position[1],
                                           a.position[2] - b.position[2]))
              : fmt::format(
                    "body '{}' at {} may overlap body '{}' of bodies[{}]: their bounding spheres and boxes "
                    "cut into each other",
                    b.name, text(b.position), a.name, entry_of[i]);
      items[entry_of[j]].fail(generated[j] ? "generate" : "position", problem);
    }
    grid.add(solids[n]);
  }
}

// A container's outside is solid: every other body (planes aside) must start inside each
// container, or the contacts would throw it through the wall.
void check_inside_containers(const std::vector<Reader>& items, const std::vector<Body>& bodies,
                             const std::vector<std::size_t>& entry_of, const std::vector<bool>& generated) {
  for (const Body& c : bodies) {
    if (!c.shape.container) continue;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      const Body& b = bodies[i];
      if (b.shape.container || b.shape.type == ShapeType::Plane) continue;
      if (const double gap = room(c, b.position); gap < 0)
        items[entry_of[i]].fail(generated[i] ? "generate" : "position",
                                fmt::format("body '{}' at {} is outside container '{}' (its wall by {:g} m): a "
                                            "container's outside is solid",
                                            b.name, text(b.position), c.name, -gap));
    }
  }
}

}  // namespace

fs::path existing_file(const Reader& r, const fs::path& dir) {
  const fs::path file = (dir / r.string("file")).lexically_normal();
  if (!fs::is_regular_file(file)) r.fail("file", "no such file: " + file.string());
  return file;
}

std::optional<std::string> make_unit(Quat& q) {
  const double length = norm(q);
  if (std::abs(length - 1) > unit_tolerance) return fmt::format("not a unit quaternion (norm {:g})", length);
  q = scaled(q, 1 / length);
  return std::nullopt;
}

std::optional<std::string> outside_domain(const Body& b, const Domain& d) {
  const Vec3 h = half_extent(b.shape, b.orientation);
  Vec3 lo{}, hi{};
  for (int k = 0; k < 3; ++k) {
    lo[k] = b.position[k] - h[k];
    hi[k] = b.position[k] + h[k];
  }
  const auto problem = [&](const char* where) {
    return fmt::format("(extent {} .. {}) {} the domain {} .. {}", text(lo), text(hi), where, text(d.min), text(d.max));
  };
  for (int k = 0; k < 3; ++k) {
    if (b.fixed && (hi[k] < d.min[k] - domain_slack || lo[k] > d.max[k] + domain_slack))
      return problem("lies wholly outside");
    if (!b.fixed && (lo[k] < d.min[k] - domain_slack || hi[k] > d.max[k] + domain_slack)) return problem("is outside");
  }
  return std::nullopt;
}

Body read_common(const Reader& r, const fs::path& dir) {
  Body b;
  b.fixed = r.boolean("fixed", b.fixed);
  b.shape = read_shape(r.map("shape"), b.fixed, dir);
  if (!b.fixed || r.has("material")) b.material = read_material(r.map("material"), b.fixed);
  b.material_line = r.line("material");
  if (r.has("orientation")) {
    r.numbers("orientation", b.orientation);
    if (const auto problem = make_unit(b.orientation)) r.fail("orientation", *problem);
  }
  b.velocity = r.vec3("velocity", b.velocity);
  b.angular_velocity = r.vec3("angular_velocity", b.angular_velocity);
  return b;
}

Bodies read_bodies(const std::vector<Reader>& items, const Domain& domain, const fs::path& dir,
                   const fs::path& output) {
  Bodies out;
  std::vector<Body>& bodies = out.bodies;
  std::vector<std::size_t> entry_of;  // body -> its entry in `items`
  std::vector<bool> generated;
  std::unordered_map<std::string, std::size_t> entry_named;
  for (std::size_t e = 0; e < items.size(); ++e) {
    const Reader& r = items[e];
    std::vector<Body> made;
    if (r.has("generate")) {
      Generated g = generate_bodies(r, {domain, dir, output, bodies});
      out.generators.push_back({e, g.kind, bodies.size(), g.bodies.size()});
      made = std::move(g.bodies);
    } else {
      made.push_back(read_single(r, domain, dir));
    }
    for (Body& b : made) {
      const bool made_here = r.has("generate");
      if (const auto [first, fresh] = entry_named.try_emplace(b.name, e); !fresh)
        r.fail("name", made_here ? fmt::format("makes '{}', a name bodies[{}] has already", b.name, first->second)
                                 : fmt::format("duplicate body name (first at bodies[{}])", first->second));
      entry_of.push_back(e);
      generated.push_back(made_here);
      bodies.push_back(std::move(b));
    }
  }
  check_overlaps(items, bodies, entry_of, generated);
  check_inside_containers(items, bodies, entry_of, generated);
  return out;
}

}  // namespace cosim::scene
