// The mesh stage's entry point: a body's mesh spec becomes a welded, validated, closed TriMesh.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "mesh/mesh_limits.hpp"
#include "mesh/trimesh.hpp"

namespace mesh {

struct LoadedMesh {
  TriMesh mesh;
  std::vector<std::string> notes;  // fixes applied (e.g. flipped winding), for the user
};

// `spec` is a generator ("icosphere:3") or, with `file` set, the spec as written in the scene.
// Throws softbody::InputError whose message starts with `context` (e.g. "scene.json: bodies.0.mesh").
// A file is read within `limits` (mesh/import.hpp).
LoadedMesh load_closed_mesh(const std::string& spec, const std::filesystem::path& file, const std::string& context,
                            const MeshLimits& limits = {});

}  // namespace mesh
