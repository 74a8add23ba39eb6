// What the renderer is given of one body in one frame: its surface, positions and triangles, nothing else.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace render {

struct FrameMesh {
  std::vector<glm::vec3> positions;       // world coordinates [m], this frame
  std::vector<glm::uvec3> triangles;      // vertex indices, counter-clockwise seen from outside; the
                                          // same every frame of a run (the renderer uploads them once)
  std::vector<glm::vec3> rest_positions;  // the body at rest [m]: where its pattern is painted, so that every
                                          // frame of a run (a chunk, a resumed run) paints it alike; used once.
                                          // Empty: the first frame drawn is the rest shape
};

}  // namespace render
