// The floor square's vertex buffer.
#include "render/floor_mesh.hpp"

#include <array>

#include <glm/vec3.hpp>

namespace render {

FloorMesh::FloorMesh(float height_m, glm::vec2 centre_xz, float half_size_m) {
  const float x0 = centre_xz.x - half_size_m, x1 = centre_xz.x + half_size_m;
  const float z0 = centre_xz.y - half_size_m, z1 = centre_xz.y + half_size_m;
  // Two triangles, counter-clockwise seen from above, as a strip.
  const std::array<glm::vec3, 4> corners = {glm::vec3(x0, height_m, z1), glm::vec3(x1, height_m, z1),
                                            glm::vec3(x0, height_m, z0), glm::vec3(x1, height_m, z0)};
  glBindVertexArray(vertex_array_.get());
  glBindBuffer(GL_ARRAY_BUFFER, positions_.get());
  glBufferData(GL_ARRAY_BUFFER, sizeof corners, corners.data(), GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
  glBindVertexArray(0);
  check_gl("uploading the floor");
}

void FloorMesh::draw() const {
  glBindVertexArray(vertex_array_.get());
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
}

}  // namespace render
