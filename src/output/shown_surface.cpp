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

namespace {

// `x` (a body's simulated positions) as shown: itself, or its skin rebuilt from it.
std::span<const softbody::Vec3> shown(const sim::World& world, int body, std::span<const softbody::Vec3> x,
                                      std::vector<softbody::Vec3>& normals, std::vector<softbody::Vec3>& detailed) {
  const sim::Skin* skin = world.model.skin_of(body);
  if (skin == nullptr) return x;
  sim::skin_positions(*skin, x, world.model.bodies[static_cast<std::size_t>(body)].topology.faces, normals, detailed);
  return detailed;
}

}  // namespace

std::span<const softbody::Vec3> ShownPositions::at_rest(const sim::World& world, int body) {
  return shown(world, body, world.model.bodies[static_cast<std::size_t>(body)].rest.position_m, normals_, detailed_);
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
