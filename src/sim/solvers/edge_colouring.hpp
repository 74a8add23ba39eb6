// A greedy colouring of a body's edges: edges of one colour share no vertex, so a constraint pass can take the
// colours in order and the edges inside a colour in any order (or in parallel) with the same bits.
#pragma once

#include <array>
#include <span>
#include <vector>

namespace sim {

struct EdgeColouring {
  std::vector<int> edges;         // edge indices, colour by colour (ascending index inside a colour)
  std::vector<int> colour_start;  // colour c holds edges[colour_start[c] .. colour_start[c + 1]); colours + 1 entries
  int colours() const { return static_cast<int>(colour_start.size()) - 1; }
};

// Each edge in index order gets the smallest colour that no earlier edge at either of its vertices has (at most
// 2 × the largest valence − 1 colours). `vertex_count`: the body's vertices (edges index 0 .. vertex_count − 1).
EdgeColouring colour_edges(std::span<const std::array<int, 2>> edges, int vertex_count);

}  // namespace sim
