// World → FrameMesh.
#include "output/mesh_snapshot.hpp"

namespace output {

void snapshot_surfaces(const sim::World& world, std::vector<render::FrameMesh>& meshes) {
  const std::vector<sim::Body>& bodies = world.model.bodies;
  if (meshes.size() != bodies.size()) {
    meshes.assign(bodies.size(), {});
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      for (const softbody::Triangle& t : bodies[b].topology.faces) {
        meshes[b].triangles.emplace_back(t[0], t[1], t[2]);
      }
    }
  }
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const std::span<const softbody::Vec3> x = world.model.of(bodies[b], world.state.x);
    std::vector<glm::vec3>& positions = meshes[b].positions;
    positions.resize(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
      positions[i] = glm::vec3(static_cast<float>(x[i].x()), static_cast<float>(x[i].y()), static_cast<float>(x[i].z()));
    }
  }
}

}  // namespace output
