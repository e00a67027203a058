#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>

#include "coupler/scene/extent.hpp"
#include "coupler/scene/names.hpp"
#include "coupler/scene/sections.hpp"

namespace cosim::scene {
namespace {

namespace fs = std::filesystem;

const Range positive = Range::above(0);

// Quaternions and normals are written by hand with a few digits; a tolerance lets
// [0.7071, 0, 0, 0.7071] through, and storing the exact unit vector keeps the solvers clean.
constexpr double unit_tolerance = 1e-6;

// Touching the domain boundary is fine; floating point noise in the sum must not make it an error.
constexpr double domain_slack = 1e-12;

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

std::string text(const Vec3& v) { return fmt::format("[{:g}]", fmt::join(v, ", ")); }

fs::path existing_file(const Reader& r, const fs::path& dir) {
  const fs::path file = (dir / r.string("file")).lexically_normal();
  if (!fs::is_regular_file(file)) r.fail("file", "no such file: " + file.string());
  return file;
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

Quat read_orientation(const Reader& r) {
  Quat q{};
  r.numbers("orientation", q);
  const double length = norm(q);
  if (std::abs(length - 1) > unit_tolerance)
    r.fail("orientation", fmt::format("not a unit quaternion (norm {:g})", length));
  return scaled(q, 1 / length);
}

void check_inside(const Reader& r, const Body& b, const Domain& d) {
  const Vec3 h = half_extent(b.shape, b.orientation);
  Vec3 lo{}, hi{};
  for (int k = 0; k < 3; ++k) {
    lo[k] = b.position[k] - h[k];
    hi[k] = b.position[k] + h[k];
  }
  for (int k = 0; k < 3; ++k)
    if (lo[k] < d.min[k] - domain_slack || hi[k] > d.max[k] + domain_slack)
      r.fail("position", fmt::format("body '{}' (extent {} .. {}) is outside the domain {} .. {}", b.name, text(lo),
                                     text(hi), text(d.min), text(d.max)));
}

Body read_body(const Reader& r, const Domain& domain, const fs::path& dir) {
  Body b;
  b.name = r.string("name");
  if (!is_name(b.name)) r.fail("name", name_rule);
  b.fixed = r.boolean("fixed", b.fixed);
  b.shape = read_shape(r.map("shape"), b.fixed, dir);
  if (!b.fixed || r.has("material")) b.material = read_material(r.map("material"), b.fixed);
  b.material_line = r.line("material");
  b.position = r.vec3("position");
  if (r.has("orientation")) b.orientation = read_orientation(r);
  b.velocity = r.vec3("velocity", b.velocity);
  b.angular_velocity = r.vec3("angular_velocity", b.angular_velocity);
  r.finish();
  check_inside(r, b, domain);
  return b;
}

}  // namespace

std::vector<Body> read_bodies(const std::vector<Reader>& items, const Domain& domain, const fs::path& dir) {
  std::vector<Body> bodies;
  for (const Reader& r : items) {
    Body b = read_body(r, domain, dir);
    for (std::size_t i = 0; i < bodies.size(); ++i)
      if (bodies[i].name == b.name) r.fail("name", fmt::format("duplicate body name (first at bodies[{}])", i));
    bodies.push_back(std::move(b));
  }
  return bodies;
}

}  // namespace cosim::scene
