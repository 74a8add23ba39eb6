// The repair step of loading a mesh as the mesh stage sees it: what repair gives back, and the function that
// does it (geometry::repair_mesh, on CGAL), which the caller passes in: geometry/ is built on mesh/, not under it.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "mesh/repair_options.hpp"
#include "mesh/trimesh.hpp"

namespace mesh {

struct RepairedMesh {
  TriMesh mesh;
  std::vector<std::string> notes;  // one line per kind of change made ("repair: filled 3 holes ..."), for the user
};

using RepairStep = std::function<RepairedMesh(const TriMesh& welded, const RepairOptions& options)>;

// Repair as a body asks for it: what to change, and the step that changes it (needed when options.enabled).
struct Repair {
  RepairOptions options;
  RepairStep step;
};

}  // namespace mesh
