// A keyframed collider's motion: its pose (position, rotation, scale) at given times, interpolated linearly or
// smoothly (C¹), and the velocity field that motion gives the collider's points, so that the contact models can act
// on a vertex's velocity relative to the surface it touches.
//
// Smooth interpolation is a cubic Hermite spline per segment [t_i, t_{i+1}], u = (t − t_i)/Δt:
//   positions and scale: p(u) = h00 p_i + h10 Δt m_i + h01 p_{i+1} + h11 Δt m_{i+1} with the Catmull–Rom tangents
//     m_i = (p_{i+1} − p_{i−1}) / (t_{i+1} − t_{i−1}) (a time derivative shared by both segments: C¹ in time), and
//     m = 0 at the first and the last key (the collider holds its pose outside the keys: C¹ there too);
//   rotations: R(u) = R_i exp([φ(u)]×), φ a cubic Hermite curve in the rotation vector space from 0 to
//     φ_1 = log(R_iᵀ R_{i+1}), whose end slopes make the body angular velocity J_r(φ) φ̇ (J_r the right Jacobian of
//     SO(3), Barfoot, "State Estimation for Robotics", eq. 7.77) equal the key's: the Catmull–Rom angular velocity
//     ω_i = log(R_{i+1} R_{i−1}ᵀ) / (t_{i+1} − t_{i−1}) (world frame), 0 at the end keys.
#pragma once

#include <memory>
#include <vector>

#include <Eigen/Geometry>

#include "sim/contact/collider_shape.hpp"

namespace sim {

using Quat = Eigen::Quaterniond;

// One key of a collider's motion.
struct ColliderKey {
  double time_s = 0.0;
  Vec3 position_m = Vec3::Zero();
  Quat rotation = Quat::Identity();  // local → world
  double scale = 1.0;                // multiplies the shape's sizes (radius, half sizes, length)
};

enum class KeyInterpolation {
  Linear,  // positions and scale linear, rotations by slerp (velocity constant on each segment)
  Smooth,  // C¹: Catmull–Rom positions and scale, a Hermite spline of rotations (see the header note)
};

struct ColliderPointCache;  // sim/contact/collider_point_cache.hpp

// The keys in increasing time, or a mesh's point cache; neither: a static collider.
struct ColliderMotion {
  std::vector<ColliderKey> keys;
  KeyInterpolation interpolation = KeyInterpolation::Linear;
  std::shared_ptr<const ColliderPointCache> cache;  // a mesh's vertices over time (no keys then)
  bool moving() const { return !keys.empty() || cache != nullptr; }
};

// When the motion starts: its first key's or first sample's time [s] (0 when static).
double motion_start_s(const ColliderMotion& motion);

// A pose and its rate of change at one time.
struct ColliderPose {
  Vec3 position_m = Vec3::Zero();
  Quat rotation = Quat::Identity();
  double scale = 1.0;
  Vec3 velocity_m_per_s = Vec3::Zero();        // dp/dt
  Vec3 angular_velocity_rad_s = Vec3::Zero();  // ω, world frame: dR/dt = [ω]× R
  double scale_rate_per_s = 0.0;               // ds/dt
};

// The pose at time t (before the first key: the first key's; after the last: the last's, at rest).
ColliderPose pose_at(const ColliderMotion& motion, double time_s);

// A bound on the speed of any point of a shape moved by the motion [m/s] (0 for a static one), for the guard's
// energy budget: per segment, its travel and turn over its duration, with the rest shape's world reach as the
// lever arm and a margin for a smooth spline's overshoot. `reach` infinite (a plane): the turn is left out.
double fastest_point_speed(const ColliderMotion& motion, const Vec3& reach_m);

// The shape of `rest` (its sizes at scale 1) at the motion's pose at time t, with the velocity field of its points
// (a point-cached mesh: its vertices at t and their velocities); `rest` itself where the motion is static.
ColliderGeometry geometry_at(const ColliderGeometry& rest, const ColliderMotion& motion, double time_s);

}  // namespace sim
