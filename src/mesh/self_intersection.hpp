// Self-intersection of a triangle mesh: pairs of triangles (sharing no vertex) that cross each other, found
// with a uniform grid over the triangles' bounding boxes. A surface that passes through itself encloses no
// well-defined volume: the gas pressure then acts on a signed sum of overlapping regions.
#pragma once

#include <utility>
#include <vector>

#include "mesh/trimesh.hpp"

namespace mesh {

struct SelfIntersections {
  long long pairs = 0;                // crossing pairs of triangles
  std::pair<int, int> first{-1, -1};  // one crossing pair (the first found)
  bool checked = false;               // false when the mesh has more than kMaxTrianglesChecked triangles
};

// Meshes larger than this are not checked (the grid's cost grows with the triangles' overlap).
inline constexpr std::size_t kMaxTrianglesChecked = 200'000;

// Counts pairs where an edge of one triangle passes through the interior of the other (coplanar overlaps,
// which need no crossing edge, are not counted).
SelfIntersections find_self_intersections(const TriMesh& mesh);

}  // namespace mesh
