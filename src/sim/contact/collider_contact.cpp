// The paper's, the friction and the positional contact against a static collider.
#include "sim/contact/collider_contact.hpp"

#include <algorithm>

#include "sim/contact/collider_side.hpp"
#include "sim/contact/contact_response.hpp"

namespace sim {
namespace {

// The restitution and friction impulse on v for the outward normal n (per unit mass).
Vec3 contact_impulse_velocity(const Vec3& v, const Vec3& n, const ContactMaterial& material) {
  const double normal_speed = v.dot(n);
  if (normal_speed >= 0.0) return v;  // already leaving: no impulse
  const double new_normal_speed = separating_speed(normal_speed, material);
  const double normal_impulse = new_normal_speed - normal_speed;  // > 0
  return tangential_after_impulse(v - normal_speed * n, normal_impulse, material) + new_normal_speed * n;
}

// Calls respond(i, s) for every vertex i in contact with the collider (s: the surface point its contact uses, the
// nearest one or, after a step through the shape, the face it came in by: sim/contact/collider_sweep.hpp), and
// counts them.
template <class Respond>
FloorContactFound for_each_inside(const ColliderGeometry& collider, const ColliderStepStart* start,
                                  std::span<const Vec3> x, Respond respond) {
  FloorContactFound found;
  SurfacePoint s;
  bool tunnelled = false;
  const ColliderSide side(collider, start, x);
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (side.clears(i, x[i]) || !collider_contact_point(collider, start, i, x[i], s, tunnelled)) continue;
    found.deepest_m = std::max(found.deepest_m, -s.distance_m);
    ++found.below;
    respond(i, s);
  }
  return found;
}

}  // namespace

FloorContactFound resolve_collider_paper(const ColliderGeometry& collider, std::span<Vec3> x, std::span<Vec3> v,
                                         std::vector<int>& reversed, const ColliderStepStart* start) {
  return for_each_inside(collider, start, x, [&](std::size_t i, const SurfacePoint& s) {
    if (collider.velocity.moving) {
      v[i] = 2.0 * surface_velocity(collider, s.closest_m) - v[i];  // v − u ← −(v − u)
    } else {
      v[i] = -v[i];
    }
    x[i] = s.closest_m;
    reversed.push_back(static_cast<int>(i));
  });
}

FloorContactFound resolve_collider_friction(const ColliderGeometry& collider, const ContactMaterial& material,
                                            std::span<Vec3> x, std::span<Vec3> v, const ColliderStepStart* start) {
  return for_each_inside(collider, start, x, [&](std::size_t i, const SurfacePoint& s) {
    x[i] = s.closest_m;
    if (collider.velocity.moving) {  // the impulse acts on the velocity relative to the surface, u
      const Vec3 u = surface_velocity(collider, s.closest_m);
      v[i] = u + contact_impulse_velocity(Vec3(v[i] - u), s.normal, material);
    } else {
      v[i] = contact_impulse_velocity(v[i], s.normal, material);
    }
  });
}

FloorContactFound resolve_collider_positional(const ColliderGeometry& collider, const ContactMaterial& material,
                                              double h, std::span<Vec3> x, std::span<Vec3> v,
                                              const ColliderStepStart* start) {
  return for_each_inside(collider, start, x, [&](std::size_t i, const SurfacePoint& s) {
    const double depth = -s.distance_m;
    x[i] = s.closest_m;
    const Vec3& n = s.normal;
    const Vec3 u = surface_velocity(collider, s.closest_m);  // the surface's velocity (0: static) [m/s]
    const Vec3 relative = collider.velocity.moving ? Vec3(v[i] - u) : v[i];
    const double normal_speed = relative.dot(n);
    Vec3 tangential = relative - normal_speed * n;  // m/s
    const double tangential_speed = tangential.norm();
    if (h * tangential_speed <= material.friction * depth) {
      x[i] -= h * tangential;  // static friction: the substep's tangential travel undone
      tangential.setZero();
    } else {
      tangential *= 1.0 - std::min(material.friction * depth / h, tangential_speed) / tangential_speed;
    }
    v[i] = tangential + (normal_speed < 0.0 ? separating_speed(normal_speed, material) : normal_speed) * n;
    if (collider.velocity.moving) v[i] += u;
  });
}

FloorContactFound resolve_collider_tunnelling(const ColliderGeometry& collider, const ColliderStepStart& start,
                                              std::span<Vec3> x, std::span<Vec3> v) {
  FloorContactFound found;
  SurfacePoint s;
  bool tunnelled = false;
  const ColliderSide side(collider, &start, x);
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (side.clears(i, x[i]) || !collider_contact_point(collider, &start, i, x[i], s, tunnelled) || !tunnelled) {
      continue;
    }
    found.deepest_m = std::max(found.deepest_m, -s.distance_m);
    ++found.below;
    x[i] = s.closest_m;
    const Vec3 u = surface_velocity(collider, s.closest_m);
    const double approach = (v[i] - u).dot(s.normal);
    if (approach < 0.0) v[i] -= approach * s.normal;  // the relative normal velocity stopped: the spring takes over
  }
  return found;
}

double deepest_inside_collider(const ColliderGeometry& collider, std::span<const Vec3> x) {
  double deepest = 0.0;
  for (const Vec3& p : x) {
    if (is_inside(collider, p)) deepest = std::max(deepest, -nearest_surface(collider, p).distance_m);
  }
  return deepest;
}

}  // namespace sim
