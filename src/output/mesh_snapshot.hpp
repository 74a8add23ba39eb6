// The bridge from simulation to renderer: copies each body's surface out of the world as a FrameMesh
// (positions and triangles, nothing else), so the renderer never sees springs, masses or the solver.
#pragma once

#include <vector>

#include "render/frame_mesh.hpp"
#include "sim/step/world.hpp"

namespace output {

// Fills `meshes` with one FrameMesh per body of `world`, of the surface it shows (output/shown_surface.hpp:
// the detailed mesh of a body simulated on a proxy): positions converted to float every call, triangles
// copied on the first call only (topology does not change during a run).
void snapshot_surfaces(const sim::World& world, std::vector<render::FrameMesh>& meshes);

}  // namespace output
