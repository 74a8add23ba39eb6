// The shapes a collider may have (plane, box, sphere, capsule, and a triangle mesh: sim/contact/collider_mesh.hpp),
// placed in the world, and the one query every contact model asks of them: a point's signed distance to the surface,
// the outward normal and the closest surface point.
#pragma once

#include <limits>
#include <memory>

#include "core/vec.hpp"

namespace sim {

using softbody::Vec3;
using Mat3 = Eigen::Matrix3d;

enum class ColliderShape {
  Plane,    // the half-space behind a plane through the position (infinite)
  Box,      // a rectangular box centred on the position
  Sphere,   // a ball centred on the position
  Capsule,  // a cylinder along the local y axis with hemispherical caps, centred on the position
  Mesh,     // a triangle mesh placed at the position: solid when closed, else a sheet of a thickness
};

struct ColliderMesh;  // sim/contact/collider_mesh.hpp

// How a collider's points move at one time (sim/contact/collider_motion.hpp): a point at x moves at
// u(x) = v + ω × (x − c) + (ṡ/s) (x − c) [m/s], c the collider's position. All zero for a static collider.
struct ColliderVelocity {
  bool moving = false;                    // false: u = 0 everywhere (and the contact models skip it)
  Vec3 linear_m_per_s = Vec3::Zero();     // v, of the position c
  Vec3 angular_rad_per_s = Vec3::Zero();  // ω, world frame
  double expansion_per_s = 0.0;           // ṡ/s, the scale's relative rate
  bool per_vertex = false;  // a point-cached mesh: u from its vertices' velocities instead (collider_point_cache.hpp)
};

// A shape and where it is: local coordinates q map to world ones as x = position + rotation q.
struct ColliderGeometry {
  ColliderShape shape = ColliderShape::Plane;
  Vec3 position_m = Vec3::Zero();
  Mat3 rotation = Mat3::Identity();          // local → world, orthonormal
  Vec3 plane_normal{0.0, 1.0, 0.0};          // plane: unit outward normal, local
  Vec3 half_size_m{0.5, 0.5, 0.5};           // box: half the edge lengths, local x, y, z [m]
  double radius_m = 0.5;                     // sphere and capsule [m]
  double half_length_m = 0.5;                // capsule: half its cylinder's length along local y [m]
  std::shared_ptr<const ColliderMesh> mesh;  // mesh: its triangles (scaled, local) and tree, shared by the copies
  // Half the sides of a world box that holds the shape [m]: is_inside() rejects a point beyond it at once. Infinite
  // (no quick rejection) until set from world_reach() once the shape's size and pose are final.
  Vec3 world_reach_m = Vec3::Constant(std::numeric_limits<double>::infinity());
  ColliderVelocity velocity;  // of its points at the time of this pose (a keyframed collider's)
};

// The velocity of a point-cached mesh's surface nearest x [m/s] (sim/contact/collider_point_cache.hpp).
Vec3 cached_surface_velocity(const ColliderGeometry& geometry, const Vec3& x);

// The velocity of the collider's point at x, u(x) [m/s] (zero for a static collider).
inline Vec3 surface_velocity(const ColliderGeometry& geometry, const Vec3& x) {
  const ColliderVelocity& u = geometry.velocity;
  if (!u.moving) return Vec3::Zero();
  if (u.per_vertex) return cached_surface_velocity(geometry, x);
  const Vec3 r = x - geometry.position_m;
  return u.linear_m_per_s + u.angular_rad_per_s.cross(r) + u.expansion_per_s * r;
}

// Half the sides of the smallest world box that holds the shape at its pose [m] (a plane: infinite).
Vec3 world_reach(const ColliderGeometry& geometry);

// What a point knows of a collider's surface.
struct SurfacePoint {
  double distance_m = 0.0;        // signed: > 0 outside, < 0 inside [m]
  Vec3 normal{0.0, 1.0, 0.0};     // unit, outward, world (where the point is on an axis, centre or medial plane: a
                                  // fixed choice, so the result is deterministic)
  Vec3 closest_m = Vec3::Zero();  // the nearest surface point, world [m]
};

SurfacePoint nearest_surface(const ColliderGeometry& geometry, const Vec3& x);

// x in the shape's own frame: q = Rᵀ (x − position) [m].
inline Vec3 to_local(const ColliderGeometry& geometry, const Vec3& x) {
  return geometry.rotation.transpose() * (x - geometry.position_m);
}

// nearest_surface() of the point whose local coordinates are q = to_local(geometry, x).
SurfacePoint nearest_surface_of_local(const ColliderGeometry& geometry, const Vec3& q);

// True when x is inside the shape (signed distance < 0), by the cheapest test: beyond world_reach_m of a box's or
// capsule's centre at once, else the shape in its own frame without square roots. The contact passes ask it of every
// vertex and nearest_surface() only of the few inside.
bool is_inside(const ColliderGeometry& geometry, const Vec3& x);

// is_inside() of x, its local coordinates q = to_local(geometry, x) already known (the continuous test needs them for
// several questions about the same point).
bool is_inside(const ColliderGeometry& geometry, const Vec3& x, const Vec3& q);

// The world box that holds a bounded shape, {lo, hi} [m]; a plane is unbounded and returns false.
bool world_bounds(const ColliderGeometry& geometry, Vec3& lo, Vec3& hi);

}  // namespace sim
