// Vertex and index buffers of a deforming body.
#include "render/body_mesh.hpp"

#include <stdexcept>
#include <vector>

namespace render {
namespace {

constexpr GLsizeiptr bytes_of(std::size_t count, std::size_t size) { return static_cast<GLsizeiptr>(count * size); }

void allocate_vertex_attribute(GLuint buffer, GLuint location, std::size_t vertex_count) {
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glBufferData(GL_ARRAY_BUFFER, bytes_of(vertex_count, sizeof(glm::vec3)), nullptr, GL_STREAM_DRAW);
  glEnableVertexAttribArray(location);
  glVertexAttribPointer(location, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
}

}  // namespace

BodyMesh::BodyMesh(std::size_t vertex_count, std::span<const glm::uvec3> triangles)
    : vertex_count_(vertex_count), index_count_(triangles.size() * 3) {
  glBindVertexArray(vertex_array_.get());
  allocate_vertex_attribute(positions_.get(), 0, vertex_count_);
  allocate_vertex_attribute(normals_.get(), 1, vertex_count_);
  allocate_vertex_attribute(pattern_coordinates_.get(), 2, vertex_count_);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_.get());
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, bytes_of(triangles.size(), sizeof(glm::uvec3)), triangles.data(),
               GL_STATIC_DRAW);
  glBindVertexArray(0);
  check_gl("allocating a body's buffers");
}

void BodyMesh::update(std::span<const glm::vec3> positions, std::span<const glm::vec3> normals,
                      std::span<const glm::vec3> rest_positions) {
  if (positions.size() != vertex_count_ || normals.size() != vertex_count_ ||
      (!rest_positions.empty() && rest_positions.size() != vertex_count_)) {
    throw std::logic_error("BodyMesh::update: the vertex count changed during the run");
  }
  if (!has_pattern_coordinates_) {
    const std::span<const glm::vec3> painted = rest_positions.empty() ? positions : rest_positions;
    glm::vec3 centroid(0.0f);
    for (const glm::vec3& p : painted) centroid += p / float(vertex_count_);
    std::vector<glm::vec3> coordinates(painted.begin(), painted.end());
    for (glm::vec3& c : coordinates) c -= centroid;
    glBindBuffer(GL_ARRAY_BUFFER, pattern_coordinates_.get());
    glBufferSubData(GL_ARRAY_BUFFER, 0, bytes_of(vertex_count_, sizeof(glm::vec3)), coordinates.data());
    has_pattern_coordinates_ = true;
  }
  glBindBuffer(GL_ARRAY_BUFFER, positions_.get());
  glBufferSubData(GL_ARRAY_BUFFER, 0, bytes_of(vertex_count_, sizeof(glm::vec3)), positions.data());
  glBindBuffer(GL_ARRAY_BUFFER, normals_.get());
  glBufferSubData(GL_ARRAY_BUFFER, 0, bytes_of(vertex_count_, sizeof(glm::vec3)), normals.data());
}

void BodyMesh::draw() const {
  glBindVertexArray(vertex_array_.get());
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(index_count_), GL_UNSIGNED_INT, nullptr);
}

}  // namespace render
