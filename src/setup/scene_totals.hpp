// The whole scene's size against its "limits": vertices and triangles summed over every body's mesh and
// simulation proxy and every collider's mesh, so that many bodies and colliders that each fit the per-file limits
// cannot exhaust the memory together.
#pragma once

#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace setup {

struct MeshSize {
  long long vertices = 0;
  long long triangles = 0;
};

// The size of a generator's mesh without building it ("icosphere:7": 163,842 vertices, 327,680 triangles);
// the spec must be a valid generator (mesh::generator_spec_error is empty).
MeshSize generator_size(const std::string& spec);

// The running totals of build_world: every body and mesh collider counts what it is known to hold (a generator's
// size, a proxy's requested vertex count; a mesh file nothing) until it is built, then what it holds. check()
// refuses totals beyond the scene's limits (softbody::InputError naming the key to raise, and the largest collider
// mesh where collider meshes count), so that a scene of too many bodies, or a collider generator too large, is refused
// before the first mesh is built, and one of too many mesh files as soon as they are read.
class SceneTotals {
 public:
  explicit SceneTotals(const scene::Scene& scene);
  // Body `index` holds `size` (its mesh, or a proxy too); replaces what was known of it before.
  void count(std::size_t index, MeshSize size);
  // Mesh collider `source` (its index in scene.collider_meshes) holds `size`; replaces what was known of it before.
  void count_collider(std::size_t source, MeshSize size);
  void check() const;

 private:
  const scene::Scene& scene_;
  std::vector<MeshSize> bodies_;
  std::vector<MeshSize> colliders_;  // per scene.collider_meshes
};

}  // namespace setup
