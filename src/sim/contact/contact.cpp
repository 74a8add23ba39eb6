// Floor contact models.
#include "sim/contact/contact.hpp"

#include <algorithm>

#include "sim/contact/contact_response.hpp"

namespace sim {

FloorContactFound resolve_floor_paper(double height_m, std::span<Vec3> x, std::span<Vec3> v,
                                      std::vector<int>& reversed) {
  FloorContactFound found;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (x[i].y() >= height_m) continue;
    found.deepest_m = std::max(found.deepest_m, height_m - x[i].y());
    ++found.below;
    v[i] = -v[i];
    x[i].y() = height_m;
    reversed.push_back(static_cast<int>(i));
  }
  return found;
}

double deepest_below_floor(double height_m, std::span<const Vec3> x) {
  double deepest = 0.0;
  for (const Vec3& p : x) deepest = std::max(deepest, height_m - p.y());
  return deepest;
}

FloorContactFound resolve_floor_friction(double height_m, const ContactMaterial& material, std::span<Vec3> x,
                                         std::span<Vec3> v) {
  FloorContactFound found;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (x[i].y() >= height_m) continue;
    found.deepest_m = std::max(found.deepest_m, height_m - x[i].y());
    ++found.below;
    x[i].y() = height_m;
    const double normal_speed = v[i].y();  // the floor's normal is +y
    if (normal_speed >= 0.0) continue;     // already leaving: no impulse
    const double new_normal_speed = separating_speed(normal_speed, material);
    const double normal_impulse = new_normal_speed - normal_speed;  // per unit mass, > 0
    const Vec3 tangential = tangential_after_impulse(Vec3(v[i].x(), 0.0, v[i].z()), normal_impulse, material);
    v[i] = Vec3(tangential.x(), new_normal_speed, tangential.z());
  }
  return found;
}

FloorContactFound resolve_floor_positional(double height_m, const ContactMaterial& material, double h,
                                           std::span<Vec3> x, std::span<Vec3> v) {
  FloorContactFound found;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (x[i].y() >= height_m) continue;
    const double depth = height_m - x[i].y();
    found.deepest_m = std::max(found.deepest_m, depth);
    ++found.below;
    x[i].y() = height_m;
    Vec3 tangential(v[i].x(), 0.0, v[i].z());  // m/s
    const double tangential_speed = tangential.norm();
    if (h * tangential_speed <= material.friction * depth) {
      x[i] -= h * tangential;  // static friction: the substep's tangential travel undone
      tangential.setZero();
    } else {
      tangential *= 1.0 - std::min(material.friction * depth / h, tangential_speed) / tangential_speed;
    }
    const double normal_speed = v[i].y();
    v[i] = Vec3(tangential.x(), normal_speed < 0.0 ? separating_speed(normal_speed, material) : normal_speed,
                tangential.z());
  }
  return found;
}

}  // namespace sim
