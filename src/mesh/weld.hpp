// Welding: merge vertices that sit at the same place (imported meshes split them at seams).
#pragma once

#include "mesh/trimesh.hpp"

namespace mesh {

// Merges vertices closer than `relative_tolerance` × the bounding-box diagonal, drops vertices no
// triangle uses, and renumbers the triangles. Triangles are kept even if they become degenerate
// (validation reports those).
TriMesh weld(const TriMesh& mesh, double relative_tolerance = 1e-7);

}  // namespace mesh
