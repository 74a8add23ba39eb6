// Bending links: the opposite vertices of each interior edge, their rest lengths and energy.
#include "sim/forces/bending.hpp"

#include <algorithm>
#include <tuple>

#include "sim/forces/energy.hpp"

namespace sim {

std::vector<std::array<int, 2>> bending_links(std::span<const Triangle> faces) {
  // Each face's three edges as (low end, high end, the face's third vertex); an interior edge appears twice.
  std::vector<std::array<int, 3>> sides;
  sides.reserve(3 * faces.size());
  for (const Triangle& f : faces) {
    for (int k = 0; k < 3; ++k) {
      const int a = f[k], b = f[(k + 1) % 3], opposite = f[(k + 2) % 3];
      sides.push_back({std::min(a, b), std::max(a, b), opposite});
    }
  }
  std::sort(sides.begin(), sides.end());
  std::vector<std::array<int, 2>> links;
  links.reserve(sides.size() / 2);
  for (std::size_t s = 0; s + 1 < sides.size(); ++s) {
    const auto& first = sides[s];
    const auto& second = sides[s + 1];
    if (first[0] != second[0] || first[1] != second[1]) continue;
    if (first[2] != second[2]) links.push_back({std::min(first[2], second[2]), std::max(first[2], second[2])});
    ++s;  // the edge's two sides are used
  }
  std::sort(links.begin(), links.end());  // memory order for the force pass, and duplicates side by side
  links.erase(std::unique(links.begin(), links.end()), links.end());
  return links;
}

void add_bending_links(Body& body, std::span<const Vec3> x) {
  body.topology.bending_links = bending_links(body.topology.faces);
  body.rest.bending_length_m.clear();
  body.rest.bending_length_m.reserve(body.topology.bending_links.size());
  for (const auto& [a, b] : body.topology.bending_links) body.rest.bending_length_m.push_back((x[a] - x[b]).norm());
}

double bending_energy(const Body& body, std::span<const Vec3> x) {
  const DistanceConstraints& constraints = body.constraints;  // the links follow the edges
  return constraint_energy(constraints, constraints.edge_count, constraints.size(), x);
}

}  // namespace sim
