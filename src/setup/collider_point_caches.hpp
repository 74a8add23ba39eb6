// Reading a point-cached mesh collider's files: the mesh in its file's vertex order and the PC2 cache whose points
// follow that order, into the collider's motion (sim/contact/collider_point_cache.hpp).
#pragma once

#include "scene/scene.hpp"

namespace setup {

// Fills `collider`'s shape (the cache's first pose) and motion from `source`'s mesh and cache. The mesh is an OBJ
// file (read as written: the cache has one point per `v` line, in order) or a generator; vertices at the same place
// in it are welded (each then follows the first's point). Throws softbody::InputError naming the scene, the key and
// the file: a mesh of another format, a cache that cannot be read (mesh/pc2_file.hpp), or one whose points per
// sample differ from the mesh's vertices.
void load_collider_point_cache(const scene::Scene& scene, const scene::ColliderMeshSource& source,
                               sim::Collider& collider);

}  // namespace setup
