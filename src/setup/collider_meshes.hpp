// The mesh colliders' files read into their shapes: the mesh loader's reading, limits and welding, then the scale,
// and the collider mesh's tree (sim/contact/collider_mesh.hpp).
#pragma once

#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "setup/scene_totals.hpp"

namespace setup {

// Fills the shape of every "mesh" collider of `scene` in `colliders` (the model's copy of scene.colliders), counting
// each in `totals` as it is read (and checking them). An open mesh gets a note (a two-sided sheet). Throws
// softbody::InputError naming the scene, the key and the file when a file cannot be read as a triangle mesh within
// the scene's limits, or the scene's totals when they pass theirs.
void load_collider_meshes(const scene::Scene& scene, std::vector<sim::Collider>& colliders,
                          std::vector<std::string>& notes, SceneTotals& totals);

}  // namespace setup
