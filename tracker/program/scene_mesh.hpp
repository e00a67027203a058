// The tracker's mesh as the scene describes it (`participants.tracker.options.mesh`):
//
//   mesh:
//     type: box                    # box | gmsh | voronoi
//     cells: [64, 64, 64]          # box: over the scene's domain
//     ratio: [1, 1, 1]             # box, optional: last cell width / first, per axis
//     tetrahedra: false            # box, optional: six tetrahedra per hexahedron
//     file: channel.msh            # gmsh: relative to the scene file
//     points: 1000                 # voronoi: uniform random sites in the domain
//     seed: 1                      # voronoi: of the sites
//     periodic: [false, false, false]   # box and voronoi, optional: linked sides, no walls
//     perturb: {fraction: 0.05, seed: 1}  # optional, any type: non-planar faces
//
// A mesh that cannot be built (a file Gmsh cannot read, a mesh that fails validation) is a
// scene::SceneError naming the key, with the mesh's own report.
#pragma once

#include "coupler/scene/reader.hpp"
#include "tracker/mesh/box_mesh.hpp"

#include <functional>
#include <optional>

namespace cosim::tracker::program {

struct SceneMesh {
  mesh::Mesh mesh;
  std::optional<mesh::BoxSpec> box;  // the mesh is this box's (not perturbed)
};
// `box_part`, if given: builds the mesh of a box (not perturbed) from its spec instead of
// box_mesh (a rank's part of it).
SceneMesh read_mesh(const scene::Reader& mesh, const scene::Scene& scene,
                    const std::function<mesh::Mesh(const mesh::BoxSpec&)>& box_part = {});

}  // namespace cosim::tracker::program
