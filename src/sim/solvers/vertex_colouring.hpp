// A greedy colouring of a body's vertices: vertices of one colour share no constraint and no face, so a solver that
// visits the vertices colour by colour may take those of one colour in any order (or at once) with the same result.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "core/vec.hpp"

namespace sim {

struct VertexColouring {
  std::vector<int> vertices;  // vertex indices, colour by colour (ascending index inside a colour)
  std::vector<int>
      colour_start;  // colour c holds vertices[colour_start[c] .. colour_start[c + 1]); colours + 1 entries
  int colours() const { return static_cast<int>(colour_start.size()) - 1; }
};

// Each vertex in index order gets the smallest colour that none of its neighbours coloured before it has, where
// the ends of every pair in `links` (edges, bending links) and the corners of every face in `faces` are neighbours.
VertexColouring colour_vertices(std::span<const std::array<int, 2>> links, std::span<const softbody::Triangle> faces,
                                int vertex_count);

}  // namespace sim
