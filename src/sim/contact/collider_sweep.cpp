// Continuous contact against a collider: the segment of a step against the shape, in the shape's own frame.
#include "sim/contact/collider_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "sim/contact/collider_mesh.hpp"
#include "sim/contact/collider_point_cache.hpp"

namespace sim {
namespace {

// How much larger the shape is at `to` than at `from` (its scale's ratio).
double size_ratio(const ColliderGeometry& from, const ColliderGeometry& to) {
  switch (to.shape) {
    case ColliderShape::Plane: return 1.0;
    case ColliderShape::Box: return to.half_size_m.x() / from.half_size_m.x();
    case ColliderShape::Sphere:
    case ColliderShape::Capsule: return to.radius_m / from.radius_m;
    case ColliderShape::Mesh: return 1.0;  // a mesh collider's keys do not scale it
  }
  return 1.0;
}

// The first t in [0, 1] where a + t d meets the sphere |q − c| = r from outside.
std::optional<double> sphere_entry(const Vec3& a, const Vec3& d, const Vec3& centre, double radius) {
  const Vec3 offset = a - centre;
  const double dd = d.squaredNorm(), od = offset.dot(d), c = offset.squaredNorm() - radius * radius;
  if (c < 0.0) return 0.0;  // already inside
  const double discriminant = od * od - dd * c;
  if (dd == 0.0 || discriminant < 0.0) return std::nullopt;
  const double t = (-od - std::sqrt(discriminant)) / dd;
  if (t < 0.0 || t > 1.0) return std::nullopt;
  return t;
}

// Capsule: the first entry among its cylinder (hits within its length) and its two end spheres. The union's first
// entry is the earliest of its convex pieces'.
std::optional<double> capsule_entry(const Vec3& a, const Vec3& d, double radius, double half_length) {
  std::optional<double> first;
  const auto keep = [&](std::optional<double> t) {
    if (t && (!first || *t < *first)) first = t;
  };
  keep(sphere_entry(a, d, Vec3(0.0, half_length, 0.0), radius));
  keep(sphere_entry(a, d, Vec3(0.0, -half_length, 0.0), radius));
  // The infinite cylinder x² + z² = r²: a quadratic in t over the x and z parts.
  const double dd = d.x() * d.x() + d.z() * d.z(), ad = a.x() * d.x() + a.z() * d.z();
  const double c = a.x() * a.x() + a.z() * a.z() - radius * radius;
  const double discriminant = ad * ad - dd * c;
  if (c >= 0.0 && dd > 0.0 && discriminant >= 0.0) {
    const double t = (-ad - std::sqrt(discriminant)) / dd;
    if (t >= 0.0 && t <= 1.0 && std::abs(a.y() + t * d.y()) <= half_length) keep(t);
  }
  return first;
}

// Box of half sizes b: the slabs' latest entry (Kay & Kajiya), before every exit; `axis` the face it enters by.
std::optional<double> box_entry(const Vec3& a, const Vec3& d, const Vec3& half, int& axis) {
  double enter = -std::numeric_limits<double>::infinity(), leave = std::numeric_limits<double>::infinity();
  axis = -1;
  for (int k = 0; k < 3; ++k) {
    if (d[k] == 0.0) {
      if (std::abs(a[k]) > half[k]) return std::nullopt;  // parallel to this slab, outside it
      continue;
    }
    const double t1 = (-half[k] - a[k]) / d[k], t2 = (half[k] - a[k]) / d[k];
    if (std::min(t1, t2) > enter) {
      enter = std::min(t1, t2);
      axis = k;
    }
    leave = std::min(leave, std::max(t1, t2));
  }
  if (axis < 0 || enter > leave || enter > 1.0 || enter < 0.0) return std::nullopt;
  return enter;
}

// The local segment a → b against the local shape: the entry's point and normal (local).
bool local_entry(const ColliderGeometry& g, const Vec3& a, const Vec3& b, Vec3& point, Vec3& normal) {
  const Vec3 d = b - a;
  switch (g.shape) {
    case ColliderShape::Plane: {
      const double da = g.plane_normal.dot(a), db = g.plane_normal.dot(b);
      if (da < 0.0 || db >= 0.0) return false;
      point = a + (da / (da - db)) * d;
      normal = g.plane_normal;
      return true;
    }
    case ColliderShape::Sphere: {
      const std::optional<double> t = sphere_entry(a, d, Vec3::Zero(), g.radius_m);
      if (!t) return false;
      point = a + *t * d;
      normal = point.norm() > 0.0 ? Vec3(point.normalized()) : Vec3::UnitY();
      return true;
    }
    case ColliderShape::Capsule: {
      const std::optional<double> t = capsule_entry(a, d, g.radius_m, g.half_length_m);
      if (!t) return false;
      point = a + *t * d;
      const Vec3 out(point.x(), point.y() - std::clamp(point.y(), -g.half_length_m, g.half_length_m), point.z());
      normal = out.norm() > 0.0 ? Vec3(out.normalized()) : Vec3::UnitX();
      return true;
    }
    case ColliderShape::Box: {
      int axis = -1;
      const std::optional<double> t = box_entry(a, d, g.half_size_m, axis);
      if (!t) return false;
      point = a + *t * d;
      normal = Vec3::Zero();
      normal[axis] = d[axis] > 0.0 ? -1.0 : 1.0;
      return true;
    }
    case ColliderShape::Mesh: return mesh_segment_entry_local(*g.mesh, a, b, point, normal);
  }
  return false;
}

// True when the segment's box, grown by `pad`, misses the shape's world box (no contact possible).
bool far_from(const ColliderGeometry& g, const Vec3& a, const Vec3& b, double pad = 0.0) {
  const Vec3 lo = a.cwiseMin(b) - g.position_m - Vec3::Constant(pad),
             hi = a.cwiseMax(b) - g.position_m + Vec3::Constant(pad);
  return (lo - g.world_reach_m).maxCoeff() >= 0.0 || (-hi - g.world_reach_m).maxCoeff() >= 0.0;
}

// segment_entry() of the segment whose ends have the local coordinates qa and qb.
bool segment_entry_of_local(const ColliderGeometry& g, const Vec3& qa, const Vec3& qb, SurfacePoint& entry) {
  Vec3 point, normal;
  if (!local_entry(g, qa, qb, point, normal)) return false;
  entry = {0.0, Vec3(g.rotation * normal), Vec3(g.position_m + g.rotation * point)};
  return true;
}

}  // namespace

Vec3 carried_with(const ColliderGeometry& from, const ColliderGeometry& to, const Vec3& x) {
  if (!to.velocity.moving && !from.velocity.moving) return x;
  if (to.velocity.per_vertex) return carried_with_cached_mesh(from, to, x);
  return to.position_m + size_ratio(from, to) * (to.rotation * (from.rotation.transpose() * (x - from.position_m)));
}

bool segment_entry(const ColliderGeometry& g, const Vec3& a, const Vec3& b, SurfacePoint& entry) {
  return segment_entry_of_local(g, to_local(g, a), to_local(g, b), entry);
}

bool collider_contact_point(const ColliderGeometry& g, const ColliderStepStart* start, std::size_t i, const Vec3& x1,
                            SurfacePoint& contact, bool& tunnelled) {
  tunnelled = false;
  if (start == nullptr) {
    if (!is_inside(g, x1)) return false;
    contact = nearest_surface(g, x1);
    return contact.distance_m < 0.0;
  }
  // A cached mesh carries x0 by its nearest point's travel (a tree walk): first the cheap test with the segment's
  // box grown by the farthest any vertex travels, which holds wherever the carried start may be.
  if (g.velocity.per_vertex && far_from(g, start->x[i], x1, start->travel_m)) return false;
  const Vec3 x0 = carried_with(*start->pose, g, start->x[i]);
  if (far_from(g, x0, x1)) return false;
  const Vec3 q0 = to_local(g, x0), q1 = to_local(g, x1);  // once for the questions below
  const bool inside = is_inside(g, x1, q1);
  if (inside) contact = nearest_surface_of_local(g, q1);
  // The front: where the segment entered, or the nearest surface of a start inside.
  SurfacePoint front;
  if (is_inside(g, x0, q0)) {
    front = nearest_surface_of_local(g, q0);
  } else if (!segment_entry_of_local(g, q0, q1, front)) {
    return inside && contact.distance_m < 0.0;
  }
  const double behind = (x1 - front.closest_m).dot(front.normal);  // < 0: behind the front's tangent plane [m]
  const bool through = inside ? contact.normal.dot(front.normal) <= 0.0 : behind < 0.0;
  if (!through) return inside && contact.distance_m < 0.0;
  tunnelled = true;
  contact = {std::min(behind, 0.0), front.normal, Vec3(x1 - std::min(behind, 0.0) * front.normal)};
  return true;
}

}  // namespace sim
