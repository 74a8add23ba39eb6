// The colliders written once beside the exported body frames, so that an import (Blender's) shows the whole scene:
// DIR/collider_<N>.obj (or .ply), N the collider's index in the scene's "colliders", in world coordinates (m, y up).
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "sim/model/settings.hpp"

namespace output {

// The file of collider `index` in `dir`, with extension `extension` (".obj" or ".ply").
std::filesystem::path collider_path(const std::filesystem::path& dir, std::size_t index, const std::string& extension);

// Writes every collider: a box, sphere or capsule tessellated as the renderer draws it, a mesh as its own vertices
// and triangles (placed), a plane as a square of side 2 plane_half_size_m around its point nearest the origin.
// Returns the paths written.
std::vector<std::filesystem::path> write_colliders(const std::filesystem::path& dir,
                                                   std::span<const sim::Collider> colliders,
                                                   const std::string& extension, double plane_half_size_m = 10.0);

}  // namespace output
