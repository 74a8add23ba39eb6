// From a scene to a simulation: every body's mesh loaded and validated, placed, its intent resolved, and
// the model and initial state built. The one place that speaks both the scene's and the solver's types.
#pragma once

#include <string>
#include <vector>

#include "core/after_phase.hpp"
#include "mesh/trimesh.hpp"
#include "scene/scene.hpp"
#include "sim/step/world.hpp"

namespace setup {

// The mesh placed in the world: scaled, then translated by the body's position.
std::vector<softbody::Vec3> place_mesh(const mesh::TriMesh& mesh, const scene::Body& spec);

// The world a scene describes. Notes on what was fixed while loading (e.g. a flipped winding) are appended
// to `notes`. Throws softbody::InputError naming the file and key when a mesh or an intent cannot be used.
// A body with "split": true whose mesh holds several separate closed parts becomes one body per part (in
// the order of their first triangle), its mass shared by area and its nRT by volume (the same gas pressure
// in every part); `bodies_per_scene_body`, when given, receives how many bodies each scene body became.
// `after_phase` is called after each long phase of each body: reading, repairing and checking its mesh
// (mesh::load_closed_mesh), remeshing its proxy, resolving its parameters (intent, bending links).
// `threads_when_auto`: the model's force threads where the scene leaves solver.threads at 0 (0: one per core).
sim::World build_world(const scene::Scene& scene, std::vector<std::string>& notes,
                       std::vector<int>* bodies_per_scene_body = nullptr, const softbody::AfterPhase& after_phase = {},
                       int threads_when_auto = 0);

}  // namespace setup
