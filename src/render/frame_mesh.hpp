// What the renderer is given of one body in one frame: its surface, positions and triangles, nothing else.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace render {

struct FrameMesh {
  std::vector<glm::vec3> positions;        // world coordinates [m], this frame
  std::vector<glm::uvec3> triangles;       // vertex indices, counter-clockwise seen from outside; the
                                           // same every frame of a run (the renderer uploads them once)
};

}  // namespace render
