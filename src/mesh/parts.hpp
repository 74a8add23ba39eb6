// Connected parts of a closed mesh and the vertices where surfaces only touch: what makes one file hold
// several bodies (two closed parts sharing one gas volume), found so that the user is told, or can split them.
#pragma once

#include <vector>

#include "mesh/trimesh.hpp"

namespace mesh {

struct MeshParts {
  int count = 0;
  std::vector<int> part_of_triangle;  // 0 .. count-1, parts numbered by their first triangle
};

// Triangles joined through shared edges form one part.
MeshParts edge_connected_parts(const TriMesh& mesh);

// Vertices whose triangles form more than one fan around them (surfaces that touch at a point only).
std::vector<int> pinched_vertices(const TriMesh& mesh);

// One mesh per part, each with only its own vertices (renumbered in the order they first appear).
std::vector<TriMesh> split_parts(const TriMesh& mesh, const MeshParts& parts);

}  // namespace mesh
