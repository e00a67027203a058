#include "tracker/program/scene_mesh.hpp"

#include <array>
#include <cmath>
#include <random>
#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

#include "tracker/mesh/box_mesh.hpp"
#include "tracker/mesh/gmsh_mesh.hpp"
#include "tracker/mesh/perturb.hpp"
#include "tracker/mesh/voronoi_mesh.hpp"

namespace cosim::tracker::program {
namespace {

using scene::Range;
using scene::Reader;

constexpr std::array kTypes{"box", "gmsh", "voronoi"};
enum Type : std::size_t { kBox, kGmsh, kVoronoi };

std::array<int, 3> whole(const Reader& r, const std::string& key, const std::array<double, 3>& values) {
  std::array<int, 3> out{};
  for (std::size_t a = 0; a < 3; ++a) {
    if (values[a] != std::floor(values[a])) r.fail(key, "expected whole numbers");
    out[a] = static_cast<int>(values[a]);
  }
  return out;
}

std::array<bool, 3> periodic(const Reader& r) {
  std::array<bool, 3> out{false, false, false};
  if (!r.has("periodic")) return out;
  const YAML::Node axes = r.node("periodic");
  if (!axes.IsSequence() || axes.size() != 3) r.fail("periodic", "expected three booleans [x, y, z]");
  try {
    for (std::size_t a = 0; a < 3; ++a) out[a] = axes[a].as<bool>();
  } catch (const YAML::Exception&) {
    r.fail("periodic", "expected three booleans [x, y, z]");
  }
  return out;
}

mesh::BoxSpec box(const Reader& r, const scene::Domain& domain) {
  std::array<double, 3> cells{}, ratio{1, 1, 1};
  r.numbers("cells", cells, Range::closed(1, 1e6));
  if (r.has("ratio")) r.numbers("ratio", ratio, Range::above(0));
  mesh::BoxSpec spec;
  const std::array<int, 3> n = whole(r, "cells", cells);
  for (std::size_t a = 0; a < 3; ++a)
    spec.axes[a] = {.min = domain.min[a], .max = domain.max[a], .cells = n[a], .ratio = ratio[a]};
  spec.tetrahedra = r.boolean("tetrahedra", false);
  spec.periodic = periodic(r);
  // Cells are numbered in 32 bits (Index) across the whole box, which no rank builds (a
  // mesh's own numbering of its faces is checked as it is built, box_mesh, on several ranks
  // per part); tetrahedra are written by their faces' vertices, numbered alike.
  const long long hexahedra = 1LL * n[0] * n[1] * n[2];
  const long long most = std::numeric_limits<Index>::max() / (spec.tetrahedra ? 72 : 1);
  if (hexahedra > most)
    r.fail("cells", std::to_string(hexahedra) + " hexahedra" +
                        (spec.tetrahedra ? " split into tetrahedra are more than their output numbers"
                                         : " are more cells than numbers count") +
                        " in 32 bits: at most " + std::to_string(most) + " hexahedra");
  return spec;
}

mesh::Mesh voronoi(const Reader& r, const scene::Domain& domain) {
  const int count = r.integer("points", Range::at_least(1));
  std::mt19937_64 rng(static_cast<std::uint64_t>(r.integer("seed", 1, Range::at_least(0))));
  mesh::VoronoiSpec spec{.min = {domain.min[0], domain.min[1], domain.min[2]},
                         .max = {domain.max[0], domain.max[1], domain.max[2]}};
  spec.periodic = periodic(r);
  std::vector<Vec3> points;
  for (int i = 0; i < count; ++i) {
    Vec3 p;
    for (int a = 0; a < 3; ++a) p[a] = std::uniform_real_distribution<double>(spec.min[a], spec.max[a])(rng);
    points.push_back(p);
  }
  return mesh::voronoi_mesh(points, spec);
}

}  // namespace

SceneMesh read_mesh(const Reader& r, const scene::Scene& scene,
                    const std::function<mesh::Mesh(const mesh::BoxSpec&)>& box_part) {
  const auto type = static_cast<Type>(r.choice("type", kTypes));
  // The key a failure of the mesh itself is blamed on.
  const std::string blamed = type == kGmsh ? "file" : type == kBox ? "cells" : "type";
  mesh::Mesh mesh;
  std::optional<mesh::BoxSpec> spec;
  try {
    switch (type) {
      case kBox:
        spec = box(r, scene.domain);
        mesh = box_part && !r.has("perturb") ? box_part(*spec) : mesh::box_mesh(*spec);
        break;
      case kGmsh:
        mesh = mesh::load_gmsh(scene.folder / r.string("file"));
        break;
      case kVoronoi:
        mesh = voronoi(r, scene.domain);
        break;
    }
    if (r.has("perturb")) {
      const Reader p = r.map("perturb");
      spec.reset();
      mesh = mesh::perturbed(std::move(mesh),
                             {.fraction = p.number("fraction", Range::open(0, 0.5)),
                              .seed = static_cast<std::uint64_t>(p.integer("seed", 1, Range::at_least(0)))});
      p.finish();
    }
  } catch (const std::invalid_argument& e) {
    r.fail(blamed, e.what());
  }
  r.finish();
  return {std::move(mesh), std::move(spec)};
}

}  // namespace cosim::tracker::program
