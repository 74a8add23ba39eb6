// assimp import: read, triangulate, flatten the node hierarchy, collect triangles.
#include "mesh/import.hpp"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "core/errors.hpp"

namespace mesh {

TriMesh import_mesh_file(const std::filesystem::path& file) {
  Assimp::Importer importer;
  // Points and lines carry no surface: drop them. Normals, UVs and materials are not needed.
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const unsigned flags = aiProcess_Triangulate | aiProcess_PreTransformVertices | aiProcess_SortByPType;
  const aiScene* scene = importer.ReadFile(file.string(), flags);
  if (scene == nullptr) {
    throw softbody::InputError("cannot be read as a mesh: " + std::string(importer.GetErrorString()));
  }
  TriMesh mesh;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* part = scene->mMeshes[m];
    const int base = static_cast<int>(mesh.vertices.size());
    for (unsigned v = 0; v < part->mNumVertices; ++v) {
      const aiVector3D& p = part->mVertices[v];
      mesh.vertices.emplace_back(p.x, p.y, p.z);
    }
    for (unsigned f = 0; f < part->mNumFaces; ++f) {
      const aiFace& face = part->mFaces[f];
      if (face.mNumIndices != 3) continue;
      mesh.triangles.push_back({base + static_cast<int>(face.mIndices[0]), base + static_cast<int>(face.mIndices[1]),
                                base + static_cast<int>(face.mIndices[2])});
    }
  }
  if (mesh.triangles.empty()) throw softbody::InputError("holds no triangles (only points or lines?)");
  return mesh;
}

}  // namespace mesh
