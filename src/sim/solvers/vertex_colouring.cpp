// Greedy vertex colouring.
#include "sim/solvers/vertex_colouring.hpp"

#include <algorithm>

namespace sim {

VertexColouring colour_vertices(std::span<const std::array<int, 2>> links, std::span<const softbody::Triangle> faces,
                                int vertex_count) {
  const auto n = static_cast<std::size_t>(vertex_count);
  std::vector<std::vector<int>> neighbours(n);
  const auto connect = [&](int a, int b) {
    neighbours[static_cast<std::size_t>(a)].push_back(b);
    neighbours[static_cast<std::size_t>(b)].push_back(a);
  };
  for (const auto& [a, b] : links) connect(a, b);
  for (const softbody::Triangle& f : faces) {
    connect(f[0], f[1]);
    connect(f[1], f[2]);
    connect(f[2], f[0]);
  }
  std::vector<int> colour_of(n, -1);
  std::vector<char> taken;
  int colours = 0;
  for (std::size_t v = 0; v < n; ++v) {
    taken.assign(static_cast<std::size_t>(colours) + 1, 0);
    for (const int u : neighbours[v]) {
      const int c = colour_of[static_cast<std::size_t>(u)];
      if (c >= 0) taken[static_cast<std::size_t>(c)] = 1;
    }
    const auto colour = static_cast<int>(std::find(taken.begin(), taken.end(), 0) - taken.begin());
    colour_of[v] = colour;
    colours = std::max(colours, colour + 1);
  }
  // Counting sort by colour, stable: ascending vertex index inside each colour.
  VertexColouring colouring;
  colouring.colour_start.assign(static_cast<std::size_t>(colours) + 1, 0);
  for (const int c : colour_of) ++colouring.colour_start[static_cast<std::size_t>(c) + 1];
  for (std::size_t c = 1; c < colouring.colour_start.size(); ++c)
    colouring.colour_start[c] += colouring.colour_start[c - 1];
  colouring.vertices.resize(n);
  std::vector<int> next(colouring.colour_start.begin(), colouring.colour_start.end() - 1);
  for (std::size_t v = 0; v < n; ++v) {
    colouring.vertices[static_cast<std::size_t>(next[static_cast<std::size_t>(colour_of[v])]++)] = static_cast<int>(v);
  }
  return colouring;
}

}  // namespace sim
