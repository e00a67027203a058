#include "tracker/program/csg_shape.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <sstream>

#include "coupler/scene/eigen.hpp"
#include "coupler/scene/error.hpp"
#include "tracker/csg/shapes.hpp"

namespace cosim::tracker::program {
namespace {

using scene::Range;
using scene::Reader;

// In the order of Kind.
constexpr std::array kKinds{"ball",         "half_space", "cylinder",   "capped_cylinder", "box",     "union",
                            "intersection", "difference", "complement", "transform",       "lattice", "balls"};
enum Kind : std::size_t {
  kBall,
  kHalfSpace,
  kCylinder,
  kCappedCylinder,
  kBox,
  kUnion,
  kIntersection,
  kDifference,
  kComplement,
  kTransform,
  kLattice,
  kBalls
};

std::vector<csg::Expression> shapes(const Reader& r, const std::string& key, const std::filesystem::path& folder) {
  std::vector<csg::Expression> out;
  for (const Reader& s : r.maps(key)) out.push_back(read_shape(s, folder));
  if (out.empty()) r.fail(key, "needs at least one shape");
  return out;
}

Eigen::Quaterniond orientation(const Reader& r) {
  if (!r.has("orientation")) return Eigen::Quaterniond::Identity();
  std::array<double, 4> q{};
  r.numbers("orientation", q);
  const Eigen::Quaterniond out(q[0], q[1], q[2], q[3]);
  if (!(out.norm() > 0)) r.fail("orientation", "must not be zero");
  return out.normalized();
}

csg::Expression transform(const Reader& r, const std::filesystem::path& folder) {
  Eigen::Affine3d t = Eigen::Affine3d::Identity();
  t.translate(scene::to_eigen(r.vec3("translate", {0, 0, 0})));
  if (r.has("rotate")) {
    const Reader rot = r.map("rotate");
    const Eigen::Vector3d axis = scene::to_eigen(rot.vec3("axis"));
    if (!(axis.norm() > 0)) rot.fail("axis", "must not be zero");
    t.rotate(Eigen::AngleAxisd(rot.number("angle"), axis.normalized()));
    rot.finish();
  }
  return csg::Expression::transformed(t, read_shape(r.map("shape"), folder));
}

csg::Expression lattice(const Reader& r, const std::filesystem::path& folder) {
  const csg::Expression cell = read_shape(r.map("shape"), folder);
  const Eigen::Vector3d spacing = scene::to_eigen(r.vec3("spacing"));
  std::array<double, 3> count{};
  r.numbers("count", count, Range::at_least(1));
  for (double n : count)
    if (n != std::floor(n)) r.fail("count", "expected whole numbers of copies");
  std::vector<csg::Expression> copies;
  for (int i = 0; i < static_cast<int>(count[0]); ++i)
    for (int j = 0; j < static_cast<int>(count[1]); ++j)
      for (int k = 0; k < static_cast<int>(count[2]); ++k) {
        Eigen::Affine3d t = Eigen::Affine3d::Identity();
        t.translate(spacing.cwiseProduct(Eigen::Vector3d(i, j, k)));
        copies.push_back(csg::Expression::transformed(t, cell));
      }
  return csg::Expression::unite(copies);
}

csg::Expression balls_file(const Reader& r, const std::filesystem::path& folder) {
  const std::filesystem::path path = folder / r.string("file");
  std::ifstream in(path);
  if (!in) r.fail("file", "cannot read " + path.string());
  std::vector<csg::Expression> balls;
  std::string text;
  for (int line = 1; std::getline(in, text); ++line) {
    text = text.substr(0, text.find('#'));
    std::istringstream fields(text);
    double x, y, z, radius;
    if (!(fields >> x)) continue;  // blank or comment
    std::string rest;
    if (!(fields >> y >> z >> radius) || (fields >> rest) || !(radius > 0))
      r.fail("file", path.string() + ":" + std::to_string(line) + ": expected \"x y z r\" with r > 0");
    balls.push_back(csg::ball({x, y, z}, radius));
  }
  if (balls.empty()) r.fail("file", path.string() + " holds no balls");
  return csg::Expression::unite(balls);
}

csg::Expression primitive(std::size_t kind, const Reader& r) {
  switch (kind) {
    case kBall:
      return csg::ball(scene::to_eigen(r.vec3("centre")), r.number("radius", Range::above(0)));
    case kHalfSpace:
      return csg::half_space(scene::to_eigen(r.vec3("point")), scene::to_eigen(r.vec3("normal")));
    case kCylinder:
      return csg::cylinder(scene::to_eigen(r.vec3("point")), scene::to_eigen(r.vec3("axis")),
                           r.number("radius", Range::above(0)));
    case kCappedCylinder:
      return csg::capped_cylinder(scene::to_eigen(r.vec3("base")), scene::to_eigen(r.vec3("top")),
                                  r.number("radius", Range::above(0)));
    default:
      return csg::box(scene::to_eigen(r.vec3("centre")), scene::to_eigen(r.vec3("half_extents", Range::above(0))),
                      orientation(r));
  }
}

// A sub-mapping read whole by `read`.
template <typename Read>
csg::Expression from_map(const Reader& shape, const std::string& key, const Read& read) {
  const Reader r = shape.map(key);
  csg::Expression out = read(r);
  r.finish();
  return out;
}

csg::Expression read_kind(Kind kind, const Reader& shape, const std::string& key, const std::filesystem::path& folder) {
  switch (kind) {
    case kUnion:
      return csg::Expression::unite(shapes(shape, key, folder));
    case kIntersection:
      return csg::Expression::intersect(shapes(shape, key, folder));
    case kDifference: {
      const auto parts = shapes(shape, key, folder);
      if (parts.size() != 2) shape.fail(key, "needs exactly two shapes: a minus b");
      return parts[0] - parts[1];
    }
    case kComplement:
      return ~read_shape(shape.map(key), folder);
    case kTransform:
      return from_map(shape, key, [&](const Reader& r) { return transform(r, folder); });
    case kLattice:
      return from_map(shape, key, [&](const Reader& r) { return lattice(r, folder); });
    case kBalls:
      return from_map(shape, key, [&](const Reader& r) { return balls_file(r, folder); });
    default:
      return from_map(shape, key, [&](const Reader& r) { return primitive(kind, r); });
  }
}

}  // namespace

csg::Expression read_shape(const Reader& shape, const std::filesystem::path& folder) {
  const std::vector<std::string> keys = shape.keys();
  if (keys.size() != 1) {
    if (keys.empty()) shape.fail("", "a shape is one key naming it: ball, half_space, union, ...");
    shape.fail(keys[1], "a shape is one key naming it; this one already is " + keys[0]);
  }
  const std::string& key = keys.front();
  const auto found = std::find(kKinds.begin(), kKinds.end(), key);
  if (found == kKinds.end()) {
    std::string names;
    for (const char* k : kKinds) names += (names.empty() ? "" : ", ") + std::string(k);
    shape.fail(key, "unknown shape; expected one of: " + names);
  }
  try {
    return read_kind(static_cast<Kind>(found - kKinds.begin()), shape, key, folder);
  } catch (const std::invalid_argument& e) {  // a zero axis or normal, from the builders
    shape.fail(key, e.what());
  }
}

}  // namespace cosim::tracker::program
