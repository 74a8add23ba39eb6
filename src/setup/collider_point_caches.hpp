// Reading a point-cached mesh collider's files: the mesh in its file's vertex order and the cache whose points follow
// that order (a PC2 file, or a numbered OBJ sequence), into the collider's motion
// (sim/contact/collider_point_cache.hpp).
#pragma once

#include <filesystem>
#include <vector>

#include "scene/scene.hpp"

namespace setup {

// Fills `collider`'s shape (the cache's first pose) and motion from `source`'s mesh and cache. The mesh is an OBJ
// file (read as written: the cache has one point per `v` line, in order) or a generator; vertices at the same place
// in it are welded (each then follows the first's point). A PC2 file's sample i is at frame start + i × rate; a
// sequence's file of frame number k (every file in the pattern's folder that the pattern names, in increasing k) at
// frame k; a frame f at f / fps seconds (source.cache_fps, else the scene's fps). Throws softbody::InputError naming
// the scene, the key and the file: a mesh of another format, a cache that cannot be read (mesh/pc2_file.hpp,
// mesh/obj_as_written.hpp), a sequence of no file, or a sample whose points differ from the mesh's vertices (in
// number; a sequence's file also in its triangles, which must be the first file's).
void load_collider_point_cache(const scene::Scene& scene, const scene::ColliderMeshSource& source,
                               sim::Collider& collider);

// The files `source`'s cache reads (the PC2 file, or the sequence's files in frame order; none without a cache).
std::vector<std::filesystem::path> point_cache_files(const scene::ColliderMeshSource& source);

}  // namespace setup
