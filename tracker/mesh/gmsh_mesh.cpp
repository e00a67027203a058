#include "tracker/mesh/gmsh_mesh.hpp"

#include "tracker/mesh/assemble.hpp"
#include "tracker/mesh/element_faces.hpp"
#include "tracker/mesh/validate.hpp"

#include <gmsh.h>

#include <algorithm>
#include <map>
#include <stdexcept>
#include <unordered_map>

namespace cosim::tracker::mesh {
namespace {

// Ends the Gmsh session however load_gmsh leaves.
struct Session {
  Session() {
    gmsh::initialize(0, nullptr, false);
    gmsh::option::setNumber("General.Terminal", 0);
  }
  ~Session() { gmsh::finalize(); }
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;
};

const std::vector<std::vector<int>>* faces_of_family(const std::string& name) {
  if (name.starts_with("Tetrahedron")) return &element_faces::tetrahedron;
  if (name.starts_with("Hexahedron")) return &element_faces::hexahedron;
  if (name.starts_with("Prism")) return &element_faces::prism;
  if (name.starts_with("Pyramid")) return &element_faces::pyramid;
  return nullptr;
}

using FaceKey = std::vector<std::size_t>;

FaceKey sorted(FaceKey key) {
  std::sort(key.begin(), key.end());
  return key;
}

// Sorted corner tags of every surface element in a physical group -> the group's patch.
std::map<FaceKey, Index> surface_patches(Polyhedra& poly) {
  std::map<FaceKey, Index> patch_of_face;
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, 2);
  for (const auto& [dim, tag] : groups) {
    std::string name;
    gmsh::model::getPhysicalName(dim, tag, name);
    if (name.empty()) name = std::to_string(tag);
    poly.patches.push_back(name);
    const Index patch = static_cast<Index>(poly.patches.size()) - 1;
    std::vector<int> entities;
    gmsh::model::getEntitiesForPhysicalGroup(dim, tag, entities);
    for (const int entity : entities) {
      std::vector<int> types;
      std::vector<std::vector<std::size_t>> element_tags, node_tags;
      gmsh::model::mesh::getElements(types, element_tags, node_tags, 2, entity);
      for (std::size_t t = 0; t < types.size(); ++t) {
        std::string family;
        int element_dim = 0, order = 0, nodes = 0, corners = 0;
        std::vector<double> local;
        gmsh::model::mesh::getElementProperties(types[t], family, element_dim, order, nodes, local, corners);
        for (std::size_t e = 0; e < element_tags[t].size(); ++e) {
          const auto first = node_tags[t].begin() + static_cast<std::ptrdiff_t>(e * nodes);
          patch_of_face[sorted(FaceKey(first, first + corners))] = patch;
        }
      }
    }
  }
  return patch_of_face;
}

Mesh read(const std::string& file) {
  Session session;
  try {
    gmsh::open(file);
  } catch (...) {
    throw std::invalid_argument(file + ": Gmsh cannot read it");
  }
  Polyhedra poly;
  poly.source = file;

  std::vector<std::size_t> node_tags;
  std::vector<double> coords, parametric;
  gmsh::model::mesh::getNodes(node_tags, coords, parametric);
  std::unordered_map<std::size_t, Index> vertex_of_tag;
  for (std::size_t i = 0; i < node_tags.size(); ++i) {
    vertex_of_tag.emplace(node_tags[i], static_cast<Index>(i));
    poly.vertices.emplace_back(coords[3 * i], coords[3 * i + 1], coords[3 * i + 2]);
  }
  const std::map<FaceKey, Index> patch_of_face = surface_patches(poly);

  std::vector<int> types;
  std::vector<std::vector<std::size_t>> element_tags, element_nodes;
  gmsh::model::mesh::getElements(types, element_tags, element_nodes, 3);
  for (std::size_t t = 0; t < types.size(); ++t) {
    std::string family;
    int dim = 0, order = 0, nodes = 0, corners = 0;
    std::vector<double> local;
    gmsh::model::mesh::getElementProperties(types[t], family, dim, order, nodes, local, corners);
    const auto* faces = faces_of_family(family);
    if (faces == nullptr)
      throw std::invalid_argument(file + ": unsupported volume element \"" + family + "\" (Gmsh type " +
                                  std::to_string(types[t]) + ")");
    for (std::size_t e = 0; e < element_tags[t].size(); ++e) {
      const std::size_t* corner = element_nodes[t].data() + e * nodes;
      for (const auto& face : *faces) {
        FaceKey key;
        std::vector<Index> loop;
        for (const int c : face) {
          key.push_back(corner[c]);
          const auto it = vertex_of_tag.find(corner[c]);
          if (it == vertex_of_tag.end())
            throw std::invalid_argument(file + ": element " + std::to_string(element_tags[t][e]) +
                                        " uses unknown node " + std::to_string(corner[c]));
          loop.push_back(it->second);
        }
        const auto patch = patch_of_face.find(sorted(key));
        poly.add_face(loop, patch == patch_of_face.end() ? -1 : patch->second);
      }
      poly.end_cell();
    }
  }
  // Gmsh saves only the elements of physical groups once there are any.
  if (poly.cell_faces.size() < 2)
    throw std::invalid_argument(file + ": no volume elements (with physical groups, is there a physical volume?)");
  return assemble(std::move(poly));
}

}  // namespace

Mesh load_gmsh(const std::filesystem::path& path) {
  if (!std::filesystem::is_regular_file(path)) throw std::invalid_argument(path.string() + ": no such file");
  Mesh mesh = read(path.string());
  require_valid(mesh);
  return mesh;
}

}  // namespace cosim::tracker::mesh
