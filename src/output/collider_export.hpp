// The colliders written beside the exported body frames, so that an import (Blender's) shows the whole scene:
// a static one once, DIR/collider_<N>.obj (or .ply); a keyframed one per frame (output/moving_collider_export.hpp).
// N is the collider's index in the scene's "colliders"; world coordinates (m, y up).
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "mesh/trimesh.hpp"
#include "output/input_guard.hpp"
#include "sim/model/settings.hpp"

namespace output {

// The file of collider `index` in `dir`, with extension `extension` (".obj" or ".ply").
std::filesystem::path collider_path(const std::filesystem::path& dir, std::size_t index, const std::string& extension);

// The surface of one collider's shape as placed by `geometry`: a box, sphere or capsule tessellated as the renderer
// draws it, a mesh as its own vertices and triangles (placed), a plane as a square of side 2 plane_half_size_m
// around its point nearest the origin. A shape's vertex count does not depend on its pose.
mesh::TriMesh collider_surface(const sim::ColliderGeometry& geometry, double plane_half_size_m = 10.0);

// Removes from `dir` an earlier run's whole-run collider files, collider_<N><extension> for each of `extensions`
// (whatever N), before a whole new run writes its own, so that a collider that was static then and is keyframed now
// (or had a point cache and is static now), or one the scene no longer has, leaves no file behind. Only regular files
// named exactly so, and none of `inputs`. Returns how many.
int remove_collider_files(const std::filesystem::path& dir, std::span<const std::string> extensions,
                          const std::vector<InputFile>& inputs);

// Writes every static collider (a keyframed one is left to the moving colliders' exporters). Returns the paths
// written.
std::vector<std::filesystem::path> write_colliders(const std::filesystem::path& dir,
                                                   std::span<const sim::Collider> colliders,
                                                   const std::string& extension, double plane_half_size_m = 10.0);

}  // namespace output
