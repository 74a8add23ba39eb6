// The camera's matrices (world → view → clip) and where a world point lands in the image.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "render/settings.hpp"

namespace render {

struct CameraMatrices {
  glm::mat4 view;        // world → camera (right-handed, looking down −z)
  glm::mat4 projection;  // camera → clip (OpenGL depth range −1..1)
};

// A perspective camera at `camera.position` looking at `camera.target`; `aspect` = width / height.
// Near and far planes (0.05 m, 500 m) enclose the floor out to where it has faded into the background.
CameraMatrices camera_matrices(const CameraSettings& camera, float aspect);

// Pixel coordinates of a world point in a width × height image: x to the right, y down from the
// top row (the orientation of the PNG files), pixel centres at half-integers.
glm::vec2 project_to_pixel(const CameraMatrices& matrices, const glm::vec3& world, int width_px, int height_px);

}  // namespace render
