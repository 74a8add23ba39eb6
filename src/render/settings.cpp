// Translates the validated scene into the renderer's settings (double → float, Eigen → glm).
#include "render/settings.hpp"

#include "scene/scene.hpp"

namespace render {
namespace {

glm::vec3 to_glm(const softbody::Vec3& v) {
  return {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())};
}

glm::vec3 to_glm(const std::array<float, 3>& rgb) { return {rgb[0], rgb[1], rgb[2]}; }

// Each collider at its first pose; the moving ones also kept whole, to be posed at each frame's time.
void add_colliders(RenderSettings& settings, std::span<const sim::Collider> colliders) {
  for (const sim::Collider& collider : colliders) {
    if (!collider.motion.moving()) {
      settings.colliders.push_back(collider.geometry);
      continue;
    }
    settings.colliders.push_back(sim::collider_at(collider, sim::motion_start_s(collider.motion)));
    settings.moving_colliders.push_back(collider);
  }
}

}  // namespace

RenderSettings settings_from_scene(const scene::Scene& scene) {
  RenderSettings settings;
  settings.width_px = scene.render.width_px;
  settings.height_px = scene.render.height_px;
  settings.msaa_samples = scene.render.msaa;
  settings.shadows = scene.render.shadows;
  settings.background = to_glm(scene.render.background);
  settings.camera = {to_glm(scene.camera.position_m), to_glm(scene.camera.target_m), to_glm(scene.camera.up),
                     static_cast<float>(scene.camera.fov_deg)};
  settings.light = {to_glm(scene.light.direction), to_glm(scene.light.color), scene.light.ambient};
  if (scene.floor) settings.floor_height_m = static_cast<float>(scene.floor->height_m);
  for (const scene::Body& body : scene.bodies) {
    settings.body_colors.push_back(to_glm(body.color));
    settings.body_patterns.push_back(static_cast<int>(body.pattern));
  }
  add_colliders(settings, scene.colliders);
  return settings;
}

void use_world_colliders(RenderSettings& settings, std::span<const sim::Collider> colliders) {
  settings.colliders.clear();
  settings.moving_colliders.clear();
  add_colliders(settings, colliders);
}

}  // namespace render
