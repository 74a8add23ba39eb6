// An OBJ file's vertices in the order its `v` lines give them, and its faces: what a point cache's points refer to
// (a PC2 file holds one position per `v` line, in that order). The general reader (mesh/import.hpp) does not keep
// that order, so a point-cached mesh is read here.
#pragma once

#include <filesystem>

#include "mesh/mesh_limits.hpp"
#include "mesh/trimesh.hpp"

namespace mesh {

// The `v` lines as vertices, in order, and the `f` lines as triangles (a polygon as a fan from its first corner;
// `i`, `i/t`, `i//n`, `i/t/n` corners; negative indices count back from the last vertex so far). Every other line
// (texture coordinates, normals, groups, materials, comments) is ignored. Throws softbody::InputError naming the
// file and the line: a file larger than `limits.max_file_bytes`, more vertices or triangles than the limits, a
// coordinate that is not a finite number within kMaxMeshCoordinate, a corner index outside the vertices, a face of
// fewer than three corners, or no face at all.
TriMesh read_obj_as_written(const std::filesystem::path& file, const MeshLimits& limits = {});

}  // namespace mesh
