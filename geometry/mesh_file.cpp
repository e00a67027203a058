#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <stdexcept>

#include "geometry/triangle_mesh.hpp"

namespace cosim::geometry {

TriangleMesh TriangleMesh::from_file(const std::filesystem::path& file) {
  const std::string name = file.string();
  Assimp::Importer importer;
  // Points and lines bound nothing; SortByPType splits them off so they can be removed.
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  // No JoinIdenticalVertices: it compares normals too and would keep STL corners apart;
  // the constructor welds by position. PreTransformVertices bakes node transforms (OBJ
  // groups) into one frame.
  const aiScene* scene =
      importer.ReadFile(name, aiProcess_Triangulate | aiProcess_SortByPType | aiProcess_PreTransformVertices);
  if (scene == nullptr) throw std::invalid_argument(name + ": cannot read mesh: " + importer.GetErrorString());

  std::vector<Eigen::Vector3d> vertices;
  std::vector<Triangle> triangles;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh& mesh = *scene->mMeshes[m];
    const auto offset = static_cast<std::uint32_t>(vertices.size());
    for (unsigned v = 0; v < mesh.mNumVertices; ++v)
      vertices.emplace_back(mesh.mVertices[v].x, mesh.mVertices[v].y, mesh.mVertices[v].z);
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines left after SortByPType
      triangles.push_back({offset + face.mIndices[0], offset + face.mIndices[1], offset + face.mIndices[2]});
    }
  }
  if (triangles.empty()) throw std::invalid_argument(name + ": the file has no triangles");
  return TriangleMesh(std::move(vertices), std::move(triangles), name);
}

}  // namespace cosim::geometry
