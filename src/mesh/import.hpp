// Mesh files through assimp (OBJ, PLY, STL, glTF, OFF, FBX: mesh_formats.hpp): all meshes of the file merged, node
// transforms applied, polygons triangulated. No welding or validation here.
#pragma once

#include <filesystem>
#include <functional>

#include "mesh/mesh_limits.hpp"
#include "mesh/trimesh.hpp"

namespace mesh {

// Throws softbody::InputError when the file is not a regular file, is not of an accepted format (mesh_formats.hpp),
// is larger than the limits allow or nests deeper than kMostNestingLevels (checked before assimp reads it, PLY and
// OFF headers included), names a file (a glTF buffer, an OBJ material library) that is not a regular file in its
// folder, cannot be read, holds no triangles, holds a face index past its vertices, or a coordinate that is not
// finite or beyond kMaxMeshCoordinate. assimp reads on a thread of its own; `while_reading` is called every 50 ms
// meanwhile, and may throw to stop waiting (the read is abandoned, the exception passes on).
TriMesh import_mesh_file(const std::filesystem::path& file, const MeshLimits& limits = {},
                         const std::function<void()>& while_reading = {});

}  // namespace mesh
