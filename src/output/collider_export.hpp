// The colliders written beside the exported body frames, so that an import (Blender's) shows the whole scene:
// a static one once, DIR/collider_<N>.obj (or .ply); a keyframed one per frame (output/moving_collider_export.hpp).
// N is the collider's index in the scene's "colliders"; world coordinates (m, y up).
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "mesh/trimesh.hpp"
#include "sim/model/settings.hpp"

namespace output {

// The file of collider `index` in `dir`, with extension `extension` (".obj" or ".ply").
std::filesystem::path collider_path(const std::filesystem::path& dir, std::size_t index, const std::string& extension);

// The surface of one collider's shape as placed by `geometry`: a box, sphere or capsule tessellated as the renderer
// draws it, a mesh as its own vertices and triangles (placed), a plane as a square of side 2 plane_half_size_m
// around its point nearest the origin. A shape's vertex count does not depend on its pose.
mesh::TriMesh collider_surface(const sim::ColliderGeometry& geometry, double plane_half_size_m = 10.0);

// Writes every static collider (a keyframed one is left to the moving colliders' exporters). Returns the paths
// written.
std::vector<std::filesystem::path> write_colliders(const std::filesystem::path& dir,
                                                   std::span<const sim::Collider> colliders,
                                                   const std::string& extension, double plane_half_size_m = 10.0);

}  // namespace output
