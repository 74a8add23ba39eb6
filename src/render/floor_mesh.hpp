// The floor as the GPU draws it: one large square at the floor height, uploaded once.
#pragma once

#include <glm/vec2.hpp>

#include "render/gl_objects.hpp"

namespace render {

class FloorMesh {
 public:
  // A square of side 2 · half_size_m centred under `centre_xz` at y = height_m; positions only (the
  // floor shader knows the normal is +y).
  FloorMesh(float height_m, glm::vec2 centre_xz, float half_size_m);
  void draw() const;

 private:
  GlVertexArray vertex_array_;
  GlBuffer positions_;
};

}  // namespace render
