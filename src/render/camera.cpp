// Camera matrices from position, target, up and vertical field of view.
#include "render/camera.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

namespace render {

namespace {
constexpr float kNear_m = 0.05f;
constexpr float kFar_m = 500.0f;
}  // namespace

CameraMatrices camera_matrices(const CameraSettings& camera, float aspect) {
  return {glm::lookAt(camera.position, camera.target, camera.up),
          glm::perspective(glm::radians(camera.fov_deg), aspect, kNear_m, kFar_m)};
}

glm::vec2 project_to_pixel(const CameraMatrices& matrices, const glm::vec3& world, int width_px, int height_px) {
  const glm::vec4 clip = matrices.projection * matrices.view * glm::vec4(world, 1.0f);
  const glm::vec2 ndc = glm::vec2(clip) / clip.w;  // −1..1, y up
  return {(ndc.x * 0.5f + 0.5f) * static_cast<float>(width_px), (0.5f - ndc.y * 0.5f) * static_cast<float>(height_px)};
}

}  // namespace render
