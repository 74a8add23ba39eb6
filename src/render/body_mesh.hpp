// One body as the GPU draws it: triangles uploaded once, positions and normals replaced every frame.
#pragma once

#include <cstddef>
#include <span>

#include <glm/vec3.hpp>

#include "render/gl_objects.hpp"

namespace render {

class BodyMesh {
 public:
  // Allocates buffers for `vertex_count` vertices and uploads the triangles (static for the whole run).
  BodyMesh(std::size_t vertex_count, std::span<const glm::uvec3> triangles);

  // Replaces this frame's positions and normals (the only per-frame upload). The first call also uploads
  // the pattern coordinates: those first positions relative to their centroid (the body's own frame).
  // `rest_positions` (or, when empty, the first frame's positions) set the pattern coordinates on the first call.
  void update(std::span<const glm::vec3> positions, std::span<const glm::vec3> normals,
              std::span<const glm::vec3> rest_positions);
  void draw() const;

  std::size_t vertex_count() const { return vertex_count_; }
  std::size_t triangle_count() const { return index_count_ / 3; }

 private:
  std::size_t vertex_count_;
  std::size_t index_count_;
  GlVertexArray vertex_array_;
  GlBuffer positions_;
  GlBuffer normals_;
  GlBuffer pattern_coordinates_;
  bool has_pattern_coordinates_ = false;
  GlBuffer indices_;
};

}  // namespace render
