// What the renderer needs to know about a scene besides the meshes: image, camera, light, floor, colours.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "sim/contact/collider_shape.hpp"
#include "sim/model/settings.hpp"

namespace scene {
struct Scene;
}

namespace render {

struct CameraSettings {
  glm::vec3 position{0.0f, 2.5f, 9.0f};  // m
  glm::vec3 target{0.0f, 1.2f, 0.0f};    // m
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fov_deg = 45.0f;  // vertical field of view
};

struct LightSettings {
  glm::vec3 direction{-0.4f, -1.0f, -0.35f};  // the way the light travels (towards the scene)
  glm::vec3 color{1.0f, 1.0f, 1.0f};          // linear RGB
  float ambient = 0.25f;                      // fraction of light that reaches every surface
};

struct RenderSettings {
  int width_px = 1280;
  int height_px = 720;
  int msaa_samples = 4;  // 1 renders without multisampling
  bool shadows = true;
  glm::vec3 background{0.62f, 0.72f, 0.85f};  // linear RGB
  CameraSettings camera;
  LightSettings light;
  std::optional<float> floor_height_m;           // no floor drawn when empty
  std::vector<glm::vec3> body_colors;            // linear RGB, one per body, in the scene's order
  std::vector<int> body_patterns;                // scene::Pattern as an int, one per body (0: plain)
  std::vector<sim::ColliderGeometry> colliders;  // the colliders, drawn in their own colour (none: none drawn); a
                                                 // keyframed one at its first key's pose
  std::vector<sim::Collider> moving_colliders;   // the keyframed ones, in the same order among themselves: each frame
                                                 // poses them at its time (Renderer::pose_colliders)
};

// The scene's render, camera, light, floor and body colour keys, as the renderer takes them.
RenderSettings settings_from_scene(const scene::Scene& scene);

// Draws `colliders` (the world's) instead of the scene's: setup reads a mesh collider's triangles, which the scene
// only names. A keyframed collider is drawn at its first key's pose and moved by each frame's time.
void use_world_colliders(RenderSettings& settings, std::span<const sim::Collider> colliders);

}  // namespace render
