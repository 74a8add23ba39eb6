// A keyframed collider's pose and velocity at a time: linear or C¹ Hermite interpolation of its keys.
#include "sim/contact/collider_motion.hpp"

#include <algorithm>
#include <cmath>

#include "sim/contact/collider_point_cache.hpp"

namespace sim {
namespace {

constexpr double kSmallAngle = 1e-6;  // rad: below it the series of sin and cos are exact to round-off

Mat3 hat(const Vec3& w) {
  Mat3 m;
  m << 0.0, -w.z(), w.y(), w.z(), 0.0, -w.x(), -w.y(), w.x(), 0.0;
  return m;
}

// The rotation vector φ of a unit quaternion (the shorter way round): q = (cos |φ|/2, sin |φ|/2 φ/|φ|).
Vec3 log_map(Quat q) {
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();
  const double sine = q.vec().norm();  // sin(θ/2)
  if (sine < kSmallAngle) return 2.0 * q.vec();
  return (2.0 * std::atan2(sine, q.w()) / sine) * q.vec();
}

Quat exp_map(const Vec3& phi) {
  const double angle = phi.norm();
  if (angle < kSmallAngle) return Quat(1.0, 0.5 * phi.x(), 0.5 * phi.y(), 0.5 * phi.z()).normalized();
  const Vec3 axis = phi / angle;
  return Quat(Eigen::AngleAxisd(angle, axis));
}

// SO(3)'s right Jacobian: d/dt Exp(φ) = Exp(φ) [J_r(φ) φ̇]× (Barfoot, eq. 7.77).
Mat3 right_jacobian(const Vec3& phi) {
  const double angle = phi.norm();
  const Mat3 k = hat(phi);
  if (angle < kSmallAngle) return Mat3::Identity() - 0.5 * k + (1.0 / 6.0) * k * k;
  const double a2 = angle * angle;
  return Mat3::Identity() - ((1.0 - std::cos(angle)) / a2) * k + ((angle - std::sin(angle)) / (a2 * angle)) * k * k;
}

Mat3 inverse_right_jacobian(const Vec3& phi) {
  const double angle = phi.norm();
  const Mat3 k = hat(phi);
  if (angle < kSmallAngle) return Mat3::Identity() + 0.5 * k + (1.0 / 12.0) * k * k;
  const double c = 1.0 / (angle * angle) - (1.0 + std::cos(angle)) / (2.0 * angle * std::sin(angle));
  return Mat3::Identity() + 0.5 * k + c * k * k;
}

// The cubic Hermite basis at u and its derivative d/du: {h00, h10, h01, h11}.
struct Hermite {
  double h00, h10, h01, h11;
};
Hermite hermite(double u) {
  const double u2 = u * u, u3 = u2 * u;
  return {2.0 * u3 - 3.0 * u2 + 1.0, u3 - 2.0 * u2 + u, -2.0 * u3 + 3.0 * u2, u3 - u2};
}
Hermite hermite_slope(double u) {
  const double u2 = u * u;
  return {6.0 * u2 - 6.0 * u, 3.0 * u2 - 4.0 * u + 1.0, -6.0 * u2 + 6.0 * u, 3.0 * u2 - 2.0 * u};
}

// The Catmull–Rom tangents at key i (time derivatives): zero at the first and the last key.
struct KeyTangents {
  Vec3 velocity_m_per_s = Vec3::Zero();
  Vec3 angular_velocity_rad_s = Vec3::Zero();  // world frame
  double scale_rate_per_s = 0.0;
};
KeyTangents key_tangents(const std::vector<ColliderKey>& keys, std::size_t i) {
  if (i == 0 || i + 1 >= keys.size()) return {};
  const ColliderKey &before = keys[i - 1], &after = keys[i + 1];
  const double span = after.time_s - before.time_s;
  return {(after.position_m - before.position_m) / span, log_map(after.rotation * before.rotation.conjugate()) / span,
          (after.scale - before.scale) / span};
}

ColliderPose held(const ColliderKey& key) {
  return {key.position_m, key.rotation, key.scale, Vec3::Zero(), Vec3::Zero(), 0.0};
}

ColliderPose linear_pose(const ColliderKey& a, const ColliderKey& b, double u, double span) {
  const Vec3 turn = log_map(a.rotation.conjugate() * b.rotation);  // body frame, over the segment
  ColliderPose pose;
  pose.position_m = a.position_m + u * (b.position_m - a.position_m);
  pose.rotation = a.rotation * exp_map(u * turn);
  pose.scale = a.scale + u * (b.scale - a.scale);
  pose.velocity_m_per_s = (b.position_m - a.position_m) / span;
  pose.angular_velocity_rad_s = (a.rotation * turn) / span;  // R_a Exp(uφ) φ = R_a φ
  pose.scale_rate_per_s = (b.scale - a.scale) / span;
  return pose;
}

ColliderPose smooth_pose(const std::vector<ColliderKey>& keys, std::size_t i, double u, double span) {
  const ColliderKey &a = keys[i], &b = keys[i + 1];
  const KeyTangents ta = key_tangents(keys, i), tb = key_tangents(keys, i + 1);
  const Hermite h = hermite(u), dh = hermite_slope(u);
  ColliderPose pose;
  pose.position_m = h.h00 * a.position_m + h.h10 * span * ta.velocity_m_per_s + h.h01 * b.position_m +
                    h.h11 * span * tb.velocity_m_per_s;
  pose.velocity_m_per_s = (dh.h00 * a.position_m + dh.h10 * span * ta.velocity_m_per_s + dh.h01 * b.position_m +
                           dh.h11 * span * tb.velocity_m_per_s) /
                          span;
  pose.scale =
      h.h00 * a.scale + h.h10 * span * ta.scale_rate_per_s + h.h01 * b.scale + h.h11 * span * tb.scale_rate_per_s;
  pose.scale_rate_per_s = (dh.h00 * a.scale + dh.h10 * span * ta.scale_rate_per_s + dh.h01 * b.scale +
                           dh.h11 * span * tb.scale_rate_per_s) /
                          span;
  // Rotation: R = R_a Exp(φ(u)), φ Hermite from 0 (slope: the body ω at a) to φ_1 (slope: J_r(φ_1)⁻¹ × the body ω at
  // b).
  const Vec3 turn = log_map(a.rotation.conjugate() * b.rotation);
  const Vec3 start_slope = a.rotation.conjugate() * ta.angular_velocity_rad_s;
  const Vec3 end_slope = inverse_right_jacobian(turn) * (b.rotation.conjugate() * tb.angular_velocity_rad_s);
  const Vec3 phi = h.h10 * span * start_slope + h.h01 * turn + h.h11 * span * end_slope;
  const Vec3 phi_rate = (dh.h10 * span * start_slope + dh.h01 * turn + dh.h11 * span * end_slope) / span;
  pose.rotation = a.rotation * exp_map(phi);
  pose.angular_velocity_rad_s = pose.rotation * (right_jacobian(phi) * phi_rate);  // world ω = R ω_body
  return pose;
}

}  // namespace

ColliderPose pose_at(const ColliderMotion& motion, double time_s) {
  const std::vector<ColliderKey>& keys = motion.keys;
  if (keys.empty()) return {};
  if (time_s <= keys.front().time_s) return held(keys.front());
  if (time_s >= keys.back().time_s) return held(keys.back());
  // The segment [t_i, t_{i+1}) that holds t.
  const auto after = std::upper_bound(keys.begin(), keys.end(), time_s,
                                      [](double t, const ColliderKey& key) { return t < key.time_s; });
  const auto i = static_cast<std::size_t>(after - keys.begin()) - 1;
  const double span = keys[i + 1].time_s - keys[i].time_s;
  const double u = (time_s - keys[i].time_s) / span;
  if (motion.interpolation == KeyInterpolation::Linear) return linear_pose(keys[i], keys[i + 1], u, span);
  return smooth_pose(keys, i, u, span);
}

double motion_start_s(const ColliderMotion& motion) {
  if (motion.cache) return cache_start_s(*motion.cache);
  return motion.keys.empty() ? 0.0 : motion.keys.front().time_s;
}

double fastest_point_speed(const ColliderMotion& motion, const Vec3& reach_m) {
  if (motion.cache) return motion.cache->fastest_vertex_speed_m_per_s;
  const std::vector<ColliderKey>& keys = motion.keys;
  const double lever = std::isfinite(reach_m.norm()) ? reach_m.norm() : 0.0;
  double fastest = 0.0;
  for (std::size_t i = 0; i + 1 < keys.size(); ++i) {
    const ColliderKey &a = keys[i], &b = keys[i + 1];
    const double span = b.time_s - a.time_s;
    const double turn = log_map(a.rotation.conjugate() * b.rotation).norm();
    const double grow = std::abs(b.scale - a.scale) / std::min(a.scale, b.scale);
    const double scale = std::max(a.scale, b.scale);
    fastest = std::max(fastest, ((b.position_m - a.position_m).norm() + (turn + grow) * lever * scale) / span);
  }
  constexpr double kSplineMargin = 2.0;  // a Catmull–Rom segment's speed stays within twice its neighbours' mean
  return motion.interpolation == KeyInterpolation::Smooth ? kSplineMargin * fastest : fastest;
}

ColliderGeometry geometry_at(const ColliderGeometry& rest, const ColliderMotion& motion, double time_s) {
  if (!motion.moving()) return rest;
  if (motion.cache) {  // the mesh moves, its placement does not
    ColliderGeometry g = rest;
    g.mesh = mesh_at(*motion.cache, time_s);
    g.world_reach_m = world_reach(g);
    g.velocity = {true, Vec3::Zero(), Vec3::Zero(), 0.0, true};
    return g;
  }
  const ColliderPose pose = pose_at(motion, time_s);
  ColliderGeometry g = rest;
  g.position_m = pose.position_m;
  g.rotation = pose.rotation.toRotationMatrix();
  g.half_size_m = pose.scale * rest.half_size_m;
  g.radius_m = pose.scale * rest.radius_m;
  g.half_length_m = pose.scale * rest.half_length_m;
  g.world_reach_m = world_reach(g);
  g.velocity = {true, pose.velocity_m_per_s, pose.angular_velocity_rad_s, pose.scale_rate_per_s / pose.scale, false};
  return g;
}

}  // namespace sim
