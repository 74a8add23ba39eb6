// Signed distance, outward normal and closest point of the analytic collider shapes.
#include "sim/contact/collider_shape.hpp"

#include <algorithm>
#include <cmath>

#include "sim/contact/collider_mesh.hpp"

namespace sim {
namespace {

// Plane through the origin with unit normal n (local): d = n·q.
SurfacePoint plane_local(const Vec3& normal, const Vec3& q) {
  const double d = normal.dot(q);
  return {d, normal, Vec3(q - d * normal)};
}

// Ball of radius r about the origin: d = |q| − r. At the centre the normal is +y.
SurfacePoint sphere_local(double radius, const Vec3& q) {
  const double length = q.norm();
  const Vec3 normal = length > 0.0 ? Vec3(q / length) : Vec3::UnitY();
  return {length - radius, normal, Vec3(radius * normal)};
}

// Box of half sizes b about the origin. Outside: the distance to the clamped point. Inside: the nearest face's
// (the axis whose |q_k| − b_k is largest, the first on a tie), d = |q_k| − b_k < 0.
SurfacePoint box_local(const Vec3& half, const Vec3& q) {
  const Vec3 excess = q.cwiseAbs() - half;  // per axis: > 0 beyond that pair of faces
  if (excess.maxCoeff() > 0.0) {
    const Vec3 clamped = q.cwiseMax(-half).cwiseMin(half);
    const Vec3 out = q - clamped;
    const double d = out.norm();
    return {d, Vec3(out / d), clamped};
  }
  int axis = 0;
  for (int k = 1; k < 3; ++k) {
    if (excess[k] > excess[axis]) axis = k;
  }
  const double side = q[axis] < 0.0 ? -1.0 : 1.0;
  // Built whole rather than by writing one coordinate, which the vector reads of the callers would wait for.
  const Vec3 normal(axis == 0 ? side : 0.0, axis == 1 ? side : 0.0, axis == 2 ? side : 0.0);
  const Vec3 face = side * half;
  const Vec3 closest(axis == 0 ? face.x() : q.x(), axis == 1 ? face.y() : q.y(), axis == 2 ? face.z() : q.z());
  return {excess[axis], normal, closest};
}

// Capsule: points within r of the segment from (0, −l, 0) to (0, l, 0). On the axis the normal is +x (or ±y beyond
// the segment's ends).
SurfacePoint capsule_local(double radius, double half_length, const Vec3& q) {
  const Vec3 axis_point(0.0, std::clamp(q.y(), -half_length, half_length), 0.0);
  const Vec3 out = q - axis_point;
  const double length = out.norm();
  Vec3 normal = Vec3::UnitX();
  if (length > 0.0) {
    normal = out / length;
  } else if (std::abs(q.y()) > half_length) {
    normal = Vec3(0.0, q.y() < 0.0 ? -1.0 : 1.0, 0.0);
  }
  return {length - radius, normal, Vec3(axis_point + radius * normal)};
}

SurfacePoint nearest_local(const ColliderGeometry& g, const Vec3& q) {
  switch (g.shape) {
    case ColliderShape::Plane: return plane_local(g.plane_normal, q);
    case ColliderShape::Box: return box_local(g.half_size_m, q);
    case ColliderShape::Sphere: return sphere_local(g.radius_m, q);
    case ColliderShape::Capsule: return capsule_local(g.radius_m, g.half_length_m, q);
    case ColliderShape::Mesh: return mesh_nearest_local(*g.mesh, q);
  }
  return {};
}

// Whether the point at `offset` = x − position is inside; local() gives its local coordinates, asked only when needed.
template <class Local>
bool inside_at(const ColliderGeometry& g, const Vec3& offset, Local local) {
  switch (g.shape) {
    case ColliderShape::Plane: return g.plane_normal.dot(local()) < 0.0;
    case ColliderShape::Sphere: return offset.squaredNorm() < g.radius_m * g.radius_m;
    case ColliderShape::Box:
    case ColliderShape::Capsule:
    case ColliderShape::Mesh: break;
  }
  if ((offset.cwiseAbs() - g.world_reach_m).maxCoeff() >= 0.0) return false;  // outside the world box
  const Vec3 q = local();
  if (g.shape == ColliderShape::Mesh) return mesh_inside_local(*g.mesh, q);
  if (g.shape == ColliderShape::Box) return (q.cwiseAbs() - g.half_size_m).maxCoeff() < 0.0;
  const Vec3 out(q.x(), q.y() - std::clamp(q.y(), -g.half_length_m, g.half_length_m), q.z());  // capsule
  return out.squaredNorm() < g.radius_m * g.radius_m;
}

}  // namespace

SurfacePoint nearest_surface(const ColliderGeometry& g, const Vec3& x) {
  return nearest_surface_of_local(g, to_local(g, x));
}

SurfacePoint nearest_surface_of_local(const ColliderGeometry& g, const Vec3& q) {
  const SurfacePoint local = nearest_local(g, q);
  return {local.distance_m, Vec3(g.rotation * local.normal), Vec3(g.position_m + g.rotation * local.closest_m)};
}

bool is_inside(const ColliderGeometry& g, const Vec3& x) {
  const Vec3 offset = x - g.position_m;
  return inside_at(g, offset, [&] { return Vec3(g.rotation.transpose() * offset); });
}

bool is_inside(const ColliderGeometry& g, const Vec3& x, const Vec3& q) {
  return inside_at(g, x - g.position_m, [&] { return q; });
}

Vec3 world_reach(const ColliderGeometry& g) {
  const Mat3 spread = g.rotation.cwiseAbs();
  switch (g.shape) {
    case ColliderShape::Plane: return Vec3::Constant(std::numeric_limits<double>::infinity());
    case ColliderShape::Box: return spread * g.half_size_m;
    case ColliderShape::Sphere: return Vec3::Constant(g.radius_m);
    case ColliderShape::Capsule: return spread.col(1) * g.half_length_m + Vec3::Constant(g.radius_m);
    case ColliderShape::Mesh: {  // the local box's centre c and half sides e: |R c| + |R| e
      const Vec3 centre = 0.5 * (g.mesh->lo_m + g.mesh->hi_m), half = 0.5 * (g.mesh->hi_m - g.mesh->lo_m);
      return Vec3((g.rotation * centre).cwiseAbs() + spread * half);
    }
  }
  return Vec3::Zero();
}

bool world_bounds(const ColliderGeometry& g, Vec3& lo, Vec3& hi) {
  if (g.shape == ColliderShape::Plane) return false;
  if (g.shape == ColliderShape::Mesh) {  // the mesh's own box, turned: centre position + R c, half sides |R| e
    const Vec3 centre = g.position_m + g.rotation * (0.5 * (g.mesh->lo_m + g.mesh->hi_m));
    const Vec3 half = g.rotation.cwiseAbs() * (0.5 * (g.mesh->hi_m - g.mesh->lo_m));
    lo = centre - half;
    hi = centre + half;
    return true;
  }
  const Vec3 reach = world_reach(g);
  lo = g.position_m - reach;
  hi = g.position_m + reach;
  return true;
}

}  // namespace sim
