#include "tracker/program/scene_walls.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <set>

namespace cosim::tracker::program {
namespace {

using scene::Range;
using scene::Reader;

constexpr std::array kKinds{"specular", "diffuse", "maxwell", "open", "periodic"};

std::string listed(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

}  // namespace

tracking::BoundaryCondition read_condition(const Reader& r, bool allow_periodic) {
  tracking::BoundaryCondition c;
  c.kind = static_cast<tracking::BoundaryKind>(r.choice("kind", kKinds));
  if (c.kind == tracking::BoundaryKind::periodic && !allow_periodic)
    r.fail("kind", "an obstacle wall cannot be periodic; expected specular, diffuse, maxwell or open");
  if (tracking::re_emits(c)) {
    c.temperature = r.number("temperature", Range::above(0));
    const scene::Vec3 v = r.vec3("velocity", scene::Vec3{0, 0, 0});
    c.velocity = {v[0], v[1], v[2]};
  } else if (r.has("velocity")) {
    r.fail("velocity", "only diffuse and maxwell walls move (a mirror sliding along itself reflects as one at rest)");
  }
  if (c.kind == tracking::BoundaryKind::maxwell) c.accommodation = r.number("accommodation", Range::closed(0, 1));
  r.finish();  // a temperature on a specular wall is a mistake worth naming
  return c;
}

tracking::Boundaries read_boundaries(const Reader& options, const mesh::Mesh& mesh, double mass,
                                     const parallel::Ranks& ranks) {
  // Absent: as empty, so that a mesh without walls (periodic on every axis) needs none.
  const Reader r =
      options.has("boundaries") ? options.map("boundaries") : Reader(YAML::Node(YAML::NodeType::Map), "", "");
  std::vector<long long> faces(mesh.patches.size(), 0);
  for (const mesh::Face& f : mesh.faces)
    if (f.neighbour < 0 && f.neighbour != mesh::kBeyondPart)
      faces[static_cast<std::size_t>(mesh::patch_of(f.neighbour))] = 1;
  if (mesh.partial) ranks.sum(faces);  // a part: a patch's faces may all be on other ranks
  std::set<Index> with_faces;
  for (std::size_t p = 0; p < faces.size(); ++p)
    if (faces[p] > 0) with_faces.insert(static_cast<Index>(p));

  std::optional<tracking::BoundaryCondition> fallback;
  if (r.has("default")) fallback = read_condition(r.map("default"), false);
  std::vector<std::optional<tracking::BoundaryCondition>> given(mesh.patches.size());
  for (const std::string& key : r.keys()) {
    if (key == "default") continue;
    const auto it = std::find(mesh.patches.begin(), mesh.patches.end(), key);
    if (it == mesh.patches.end()) r.fail(key, "no such patch; the mesh has: " + listed(mesh.patches) + " (or default)");
    const auto patch = static_cast<Index>(it - mesh.patches.begin());
    given[static_cast<std::size_t>(patch)] = read_condition(r.map(key), true);
    const bool periodic = given[static_cast<std::size_t>(patch)]->kind == tracking::BoundaryKind::periodic;
    if (periodic && with_faces.contains(patch))
      r.fail(key,
             "the mesh does not link this patch periodically (set mesh.periodic for its axis, box and "
             "voronoi; Gmsh meshes have no periodic links)");
    if (!periodic && !with_faces.contains(patch))
      r.fail(key, "the mesh links this patch periodically, so it has no walls; write periodic or leave it out");
  }
  r.finish();

  tracking::Boundaries b{.patches = {}, .mass = mass};
  for (std::size_t p = 0; p < mesh.patches.size(); ++p) {
    if (!with_faces.contains(static_cast<Index>(p))) {
      b.patches.push_back({.kind = tracking::BoundaryKind::periodic});
    } else if (given[p]) {
      b.patches.push_back(*given[p]);
    } else if (fallback) {
      b.patches.push_back(*fallback);
    } else {
      options.fail("boundaries", "no condition for patch " + mesh.patches[p] + " (name it or give a default)");
    }
  }
  return b;
}

}  // namespace cosim::tracker::program
