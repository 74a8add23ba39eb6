// Greedy edge colouring.
#include "sim/solvers/edge_colouring.hpp"

#include <algorithm>

namespace sim {

EdgeColouring colour_edges(std::span<const std::array<int, 2>> edges, int vertex_count) {
  // used[v]: the colours of the edges coloured so far at vertex v (a short list: at most its valence).
  std::vector<std::vector<int>> used(static_cast<std::size_t>(vertex_count));
  std::vector<int> colour_of(edges.size());
  int colours = 0;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const auto& at_i = used[static_cast<std::size_t>(edges[e][0])];
    const auto& at_j = used[static_cast<std::size_t>(edges[e][1])];
    int colour = 0;
    while (std::find(at_i.begin(), at_i.end(), colour) != at_i.end() ||
           std::find(at_j.begin(), at_j.end(), colour) != at_j.end()) {
      ++colour;
    }
    colour_of[e] = colour;
    colours = std::max(colours, colour + 1);
    used[static_cast<std::size_t>(edges[e][0])].push_back(colour);
    used[static_cast<std::size_t>(edges[e][1])].push_back(colour);
  }
  // Counting sort by colour, stable: ascending edge index inside each colour.
  EdgeColouring colouring;
  colouring.colour_start.assign(static_cast<std::size_t>(colours) + 1, 0);
  for (int c : colour_of) ++colouring.colour_start[static_cast<std::size_t>(c) + 1];
  for (std::size_t c = 1; c < colouring.colour_start.size(); ++c)
    colouring.colour_start[c] += colouring.colour_start[c - 1];
  colouring.edges.resize(edges.size());
  std::vector<int> next(colouring.colour_start.begin(), colouring.colour_start.end() - 1);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    colouring.edges[static_cast<std::size_t>(next[static_cast<std::size_t>(colour_of[e])]++)] = static_cast<int>(e);
  }
  return colouring;
}

}  // namespace sim
