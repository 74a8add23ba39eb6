// The shown surface of a body: skin or simulated surface.
#include "output/shown_surface.hpp"

namespace output {

std::span<const softbody::Triangle> shown_triangles(const sim::World& world, int body) {
  if (const sim::Skin* skin = world.model.skin_of(body)) return skin->triangles;
  return world.model.bodies[static_cast<std::size_t>(body)].topology.faces;
}

int shown_vertex_count(const sim::World& world, int body) {
  if (const sim::Skin* skin = world.model.skin_of(body)) return static_cast<int>(skin->vertex_count());
  return world.model.bodies[static_cast<std::size_t>(body)].vertex_count;
}

std::span<const softbody::Vec3> ShownPositions::of(const sim::World& world, int body) {
  const sim::Body& simulated = world.model.bodies[static_cast<std::size_t>(body)];
  const std::span<const softbody::Vec3> x = world.model.of(simulated, world.state.x);
  const sim::Skin* skin = world.model.skin_of(body);
  if (skin == nullptr) return x;
  sim::skin_positions(*skin, x, simulated.topology.faces, normals_, detailed_);
  return detailed_;
}

}  // namespace output
