// The framing camera: the distance that fits the swept box's corners, in the default view direction.
#include "render/camera_framing.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace render {

Bounds including_colliders(const Bounds& swept, std::span<const sim::ColliderGeometry> colliders) {
  Bounds box = swept;
  for (const sim::ColliderGeometry& collider : colliders) {
    softbody::Vec3 lo, hi;
    if (!sim::world_bounds(collider, lo, hi)) continue;
    box.min = glm::min(box.min,
                       glm::vec3(static_cast<float>(lo.x()), static_cast<float>(lo.y()), static_cast<float>(lo.z())));
    box.max = glm::max(box.max,
                       glm::vec3(static_cast<float>(hi.x()), static_cast<float>(hi.y()), static_cast<float>(hi.z())));
  }
  return box;
}

Bounds including_moving_colliders(const Bounds& swept, std::span<const sim::Collider> moving,
                                  std::span<const double> frame_times_s) {
  if (frame_times_s.empty()) return swept;
  const auto [first, last] = std::minmax_element(frame_times_s.begin(), frame_times_s.end());
  std::vector<sim::ColliderGeometry> poses;
  for (const sim::Collider& collider : moving) {
    for (const double time_s : frame_times_s) poses.push_back(sim::collider_at(collider, time_s));
    for (const sim::ColliderKey& key : collider.motion.keys) {
      if (key.time_s > *first && key.time_s < *last) poses.push_back(sim::collider_at(collider, key.time_s));
    }
  }
  return including_colliders(swept, poses);
}

CameraSettings frame_swept_box(const Bounds& swept, float aspect, float fov_deg, float margin) {
  const CameraSettings defaults;
  const glm::vec3 centre = 0.5f * (swept.min + swept.max);
  const glm::vec3 back = glm::normalize(defaults.position - defaults.target);  // from the target to the camera
  const glm::vec3 right = glm::normalize(glm::cross(defaults.up, back));
  const glm::vec3 up = glm::cross(back, right);
  const float tan_v = (1.0f - margin) * std::tan(glm::radians(0.5f * fov_deg));
  const float tan_h = aspect * tan_v;
  float distance = 0.0f;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p{(corner & 1) ? swept.max.x : swept.min.x, (corner & 2) ? swept.max.y : swept.min.y,
                      (corner & 4) ? swept.max.z : swept.min.z};
    const glm::vec3 d = p - centre;
    const float towards_camera = glm::dot(d, back);
    distance = std::max({distance, std::abs(glm::dot(d, right)) / tan_h + towards_camera,
                         std::abs(glm::dot(d, up)) / tan_v + towards_camera});
  }
  CameraSettings camera;
  camera.target = centre;
  camera.position = centre + std::max(distance, 0.1f) * back;
  camera.up = defaults.up;
  camera.fov_deg = fov_deg;
  return camera;
}

}  // namespace render
