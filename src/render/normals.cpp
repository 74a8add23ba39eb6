// Area-weighted vertex normals.
#include "render/normals.hpp"

#include <glm/geometric.hpp>

namespace render {

void area_weighted_normals(std::span<const glm::vec3> positions, std::span<const glm::uvec3> triangles,
                           std::vector<glm::vec3>& normals) {
  normals.assign(positions.size(), glm::vec3(0.0f));
  for (const glm::uvec3& t : triangles) {
    // The ½ is left out: it scales every sum alike and the normalisation removes it.
    const glm::vec3 area = glm::cross(positions[t.y] - positions[t.x], positions[t.z] - positions[t.x]);
    normals[t.x] += area;
    normals[t.y] += area;
    normals[t.z] += area;
  }
  for (glm::vec3& n : normals) {
    const float length = glm::length(n);
    n = length > 0.0f ? n / length : glm::vec3(0.0f, 1.0f, 0.0f);
  }
}

}  // namespace render
