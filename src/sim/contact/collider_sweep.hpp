// Continuous contact against a collider: which side of its surface a vertex came from during a step, so that no
// vertex passes through a thin shape (a board) between two steps, nor past its middle (where the nearest surface
// point is on the far side and the discrete test would push it out there).
//
// The step's segment is taken in the collider's frame at the step's end: the start position x0 is carried with the
// collider's motion from its pose at the start of the step to its pose at the end, x0' = p1 + s1/s0 R1 R0ᵀ (x0 − p0),
// so that a vertex at rest on a moving surface stays on it; against a point-cached mesh x0 is carried with its nearest
// surface point instead (the same triangle at the same barycentric weights in both poses: exact for a mesh that
// translates, close for one that deforms little in a step). The vertex's front is
//   - where the segment x0' → x1 entered the shape, when x0' is outside;
//   - the nearest surface point of x0', when x0' is inside (a smooth contact's vertex that is sinking in).
// It tunnelled when it ends inside with its nearest surface on the other side (n1·n_front ≤ 0), or outside behind
// the front's tangent plane after entering. Its contact is then the front's tangent plane, not its nearest point.
#pragma once

#include <span>

#include "sim/contact/collider_shape.hpp"

namespace sim {

// The collider's pose at the start of a step and where every vertex was then.
struct ColliderStepStart {
  const ColliderGeometry* pose = nullptr;
  std::span<const Vec3> x;
  double travel_m = 0.0;  // a point-cached mesh: the farthest any of its vertices moves in the step [m]
};

// x moved with the collider from pose `from` to pose `to` (x itself when the collider is static).
Vec3 carried_with(const ColliderGeometry& from, const ColliderGeometry& to, const Vec3& x);

// True when the segment a → b (world, at the collider's pose) enters the shape from outside; `entry` is then the
// first surface point it meets, with the outward normal there (distance 0).
bool segment_entry(const ColliderGeometry& collider, const Vec3& a, const Vec3& b, SurfacePoint& entry);

// The surface point vertex i's contact uses at the end of a step (it at x1), and whether the step took it through
// to the far side. False when it is neither inside nor tunnelled. Without `start` (nullptr): the discrete test,
// the nearest surface point of a vertex inside.
bool collider_contact_point(const ColliderGeometry& collider, const ColliderStepStart* start, std::size_t i,
                            const Vec3& x1, SurfacePoint& contact, bool& tunnelled);

}  // namespace sim
