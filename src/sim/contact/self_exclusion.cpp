// Self-collision's neighbourhoods: a walk across edges from each vertex's one-ring, by rest distance.
#include "sim/contact/self_exclusion.hpp"

#include <algorithm>

#include "sim/contact/body_collision.hpp"

namespace sim {
namespace {

double rest_distance(std::span<const Triangle> faces, std::span<const Vec3> rest, int vertex, int face) {
  const Triangle& t = faces[static_cast<std::size_t>(face)];
  return distance_to_triangle(rest[static_cast<std::size_t>(vertex)], rest[static_cast<std::size_t>(t[0])],
                              rest[static_cast<std::size_t>(t[1])], rest[static_cast<std::size_t>(t[2])]);
}

}  // namespace

SelfExclusion build_self_exclusion(std::span<const Triangle> faces, std::span<const std::array<int, 3>> across,
                                   std::span<const int> vertex_face_start, std::span<const int> vertex_faces,
                                   std::span<const Vec3> rest, double radius_m) {
  SelfExclusion exclusion;
  const int vertex_count = static_cast<int>(rest.size());
  exclusion.start.assign(1, 0);
  std::vector<int> visited_by(faces.size(), -1);  // per face: the last vertex whose walk reached it
  for (int v = 0; v < vertex_count; ++v) {
    const auto first = static_cast<std::size_t>(exclusion.faces.size());
    for (int i = vertex_face_start[static_cast<std::size_t>(v)]; i < vertex_face_start[static_cast<std::size_t>(v) + 1];
         ++i) {
      const int f = vertex_faces[static_cast<std::size_t>(i)];
      visited_by[static_cast<std::size_t>(f)] = v;
      exclusion.faces.push_back(f);
    }
    // Breadth first across edges: a face joins while it is nearer than radius_m at rest.
    for (std::size_t next = first; next < exclusion.faces.size(); ++next) {
      for (const int g : across[static_cast<std::size_t>(exclusion.faces[next])]) {
        if (g < 0 || visited_by[static_cast<std::size_t>(g)] == v) continue;
        visited_by[static_cast<std::size_t>(g)] = v;
        if (rest_distance(faces, rest, v, g) < radius_m) exclusion.faces.push_back(g);
      }
    }
    std::sort(exclusion.faces.begin() + static_cast<std::ptrdiff_t>(first), exclusion.faces.end());
    exclusion.start.push_back(static_cast<int>(exclusion.faces.size()));
  }
  return exclusion;
}

}  // namespace sim
