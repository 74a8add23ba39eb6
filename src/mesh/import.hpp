// Mesh files through assimp (OBJ, PLY, STL, glTF, FBX, ...): all meshes of the file merged, node
// transforms applied, polygons triangulated. No welding or validation here.
#pragma once

#include <filesystem>

#include "mesh/trimesh.hpp"

namespace mesh {

// Throws softbody::InputError when the file cannot be read or holds no triangles.
TriMesh import_mesh_file(const std::filesystem::path& file);

}  // namespace mesh
