// Mesh files through assimp (OBJ, PLY, STL, glTF, FBX, ...): all meshes of the file merged, node
// transforms applied, polygons triangulated. No welding or validation here.
#pragma once

#include <filesystem>

#include "mesh/mesh_limits.hpp"
#include "mesh/trimesh.hpp"

namespace mesh {

// Throws softbody::InputError when the file is not a regular file, is larger than the limits allow (checked
// before assimp reads it, PLY and OFF headers included), cannot be read, holds no triangles, holds a face
// index past its vertices, or a coordinate that is not finite or beyond kMaxMeshCoordinate.
TriMesh import_mesh_file(const std::filesystem::path& file, const MeshLimits& limits = {});

}  // namespace mesh
