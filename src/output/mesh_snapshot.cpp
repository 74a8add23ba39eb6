// World → FrameMesh.
#include "output/mesh_snapshot.hpp"

#include "output/shown_surface.hpp"

namespace output {

namespace {

void to_float(std::span<const softbody::Vec3> x, std::vector<glm::vec3>& positions) {
  positions.resize(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    positions[i] = glm::vec3(static_cast<float>(x[i].x()), static_cast<float>(x[i].y()), static_cast<float>(x[i].z()));
  }
}

}  // namespace

void snapshot_surfaces(const sim::World& world, std::vector<render::FrameMesh>& meshes) {
  const std::size_t bodies = world.model.bodies.size();
  ShownPositions shown;  // a skin's scratch (one allocation per frame: small beside drawing it)
  if (meshes.size() != bodies) {
    meshes.assign(bodies, {});
    for (std::size_t b = 0; b < bodies; ++b) {
      for (const softbody::Triangle& t : shown_triangles(world, static_cast<int>(b))) {
        meshes[b].triangles.emplace_back(t[0], t[1], t[2]);
      }
      to_float(shown.at_rest(world, static_cast<int>(b)), meshes[b].rest_positions);
    }
  }
  for (std::size_t b = 0; b < bodies; ++b) to_float(shown.of(world, static_cast<int>(b)), meshes[b].positions);
}

}  // namespace output
