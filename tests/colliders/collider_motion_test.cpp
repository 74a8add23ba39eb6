// A keyframed collider's motion: exact at its keys, held before the first and after the last, its velocity the
// derivative of its pose, and C¹ across a key with "smooth" interpolation (finite differences of the pose on each
// side of a key agree), which "linear" is not. The scene keys are read, and bad keys refused with their path.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "core/errors.hpp"
#include "core/euler_rotation.hpp"
#include "sim/contact/collider_motion.hpp"
#include "test_helpers.hpp"

namespace {

using testing_support::scene_refusal;

using sim::ColliderKey;
using sim::ColliderMotion;
using sim::ColliderPose;
using sim::KeyInterpolation;
using sim::Quat;
using softbody::Vec3;

ColliderKey key(double t, const Vec3& p, const Vec3& degrees, double scale) {
  return {t, p, Quat(softbody::rotation_xyz_degrees(degrees)), scale};
}

// Four keys at uneven times, turning about changing axes, growing and shrinking.
ColliderMotion wandering(KeyInterpolation interpolation) {
  ColliderMotion motion;
  motion.interpolation = interpolation;
  motion.keys = {key(0.0, Vec3(0, 0, 0), Vec3(0, 0, 0), 1.0), key(0.4, Vec3(1, 0.5, 0), Vec3(30, 10, 0), 1.5),
                 key(1.0, Vec3(1.5, -0.5, 1), Vec3(60, 40, 20), 0.8), key(1.3, Vec3(2, 0, 1), Vec3(90, 0, 45), 1.0)};
  return motion;
}

// The world angular velocity that turns R(a) into R(b) over b − a: log(R_b R_aᵀ) / (b − a) [rad/s].
Vec3 turn_rate(const ColliderPose& a, const ColliderPose& b, double dt) {
  const Eigen::AngleAxisd turn(b.rotation * a.rotation.conjugate());
  return turn.angle() * turn.axis() / dt;
}

// The one-sided difference quotients of the pose just before and just after time t.
struct Sides {
  Vec3 velocity_before, velocity_after, spin_before, spin_after;
  double scale_rate_before, scale_rate_after;
};
Sides one_sided(const ColliderMotion& motion, double t, double h) {
  const ColliderPose before = sim::pose_at(motion, t - h), at = sim::pose_at(motion, t),
                     after = sim::pose_at(motion, t + h);
  return {(at.position_m - before.position_m) / h,
          (after.position_m - at.position_m) / h,
          turn_rate(before, at, h),
          turn_rate(at, after, h),
          (at.scale - before.scale) / h,
          (after.scale - at.scale) / h};
}

TEST(ColliderMotion, ExactAtTheKeysAndHeldOutsideThem) {
  for (const KeyInterpolation interpolation : {KeyInterpolation::Linear, KeyInterpolation::Smooth}) {
    const ColliderMotion motion = wandering(interpolation);
    for (const ColliderKey& k : motion.keys) {
      const ColliderPose pose = sim::pose_at(motion, k.time_s);
      EXPECT_EQ(pose.position_m, k.position_m);
      EXPECT_LT((pose.rotation.toRotationMatrix() - k.rotation.toRotationMatrix()).norm(), 1e-15);
      EXPECT_EQ(pose.scale, k.scale);
    }
    const ColliderPose early = sim::pose_at(motion, -1.0), late = sim::pose_at(motion, 5.0);
    EXPECT_EQ(early.position_m, motion.keys.front().position_m);
    EXPECT_EQ(late.position_m, motion.keys.back().position_m);
    EXPECT_EQ(late.scale, motion.keys.back().scale);
    EXPECT_EQ(early.velocity_m_per_s, Vec3::Zero());
    EXPECT_EQ(late.angular_velocity_rad_s, Vec3::Zero());
  }
}

// Inside a segment the reported v, ω and ṡ are the pose's derivatives (central differences, error O(h²)).
TEST(ColliderMotion, VelocityIsTheDerivativeOfThePose) {
  constexpr double h = 1e-6;
  for (const KeyInterpolation interpolation : {KeyInterpolation::Linear, KeyInterpolation::Smooth}) {
    const ColliderMotion motion = wandering(interpolation);
    for (const double t : {0.1, 0.3, 0.55, 0.9, 1.2}) {
      const ColliderPose pose = sim::pose_at(motion, t), a = sim::pose_at(motion, t - h),
                         b = sim::pose_at(motion, t + h);
      EXPECT_LT((pose.velocity_m_per_s - (b.position_m - a.position_m) / (2 * h)).norm(), 1e-6) << t;
      EXPECT_LT((pose.angular_velocity_rad_s - turn_rate(a, b, 2 * h)).norm(), 1e-6) << t;
      EXPECT_NEAR(pose.scale_rate_per_s, (b.scale - a.scale) / (2 * h), 1e-6) << t;
    }
  }
}

// C¹: at every key the difference quotients on the two sides agree to O(h) (h = 1e-6: ~1e-5 for these motions);
// the linear motion's jump there by the change of velocity (order 1 m/s), so the test can tell them apart.
TEST(ColliderMotion, SmoothIsC1AcrossTheKeysAndLinearIsNot) {
  constexpr double h = 1e-6;
  const ColliderMotion smooth = wandering(KeyInterpolation::Smooth), linear = wandering(KeyInterpolation::Linear);
  for (const ColliderKey& k : smooth.keys) {
    const Sides s = one_sided(smooth, k.time_s, h);
    EXPECT_LT((s.velocity_before - s.velocity_after).norm(), 1e-4) << k.time_s;
    EXPECT_LT((s.spin_before - s.spin_after).norm(), 1e-4) << k.time_s;
    EXPECT_NEAR(s.scale_rate_before, s.scale_rate_after, 1e-4) << k.time_s;
  }
  for (std::size_t i = 1; i + 1 < linear.keys.size(); ++i) {
    const Sides s = one_sided(linear, linear.keys[i].time_s, h);
    EXPECT_GT((s.velocity_before - s.velocity_after).norm(), 0.1) << linear.keys[i].time_s;
    EXPECT_GT((s.spin_before - s.spin_after).norm(), 0.1) << linear.keys[i].time_s;
  }
}

// The shape's sizes follow the scale, and a point's velocity is v + ω × r + (ṡ/s) r.
TEST(ColliderMotion, GeometryAtScalesTheShapeAndGivesThePointsVelocity) {
  sim::ColliderGeometry box;
  box.shape = sim::ColliderShape::Box;
  box.half_size_m = Vec3(0.5, 0.1, 0.2);
  const ColliderMotion motion = wandering(KeyInterpolation::Smooth);
  constexpr double t = 0.7, h = 1e-6;
  const sim::ColliderGeometry g = sim::geometry_at(box, motion, t);
  EXPECT_NEAR(g.half_size_m.x(), 0.5 * sim::pose_at(motion, t).scale, 1e-15);
  // A point fixed in the box (local q) moves as x(t) = p + s R q: its velocity by differences against the field's.
  const Vec3 q(0.3, -0.05, 0.1);
  const auto world = [&](double time) {
    const sim::ColliderGeometry at = sim::geometry_at(box, motion, time);
    return Vec3(at.position_m + at.rotation * (q.cwiseProduct(at.half_size_m).cwiseQuotient(box.half_size_m)));
  };
  const Vec3 x = world(t), difference = (world(t + h) - world(t - h)) / (2 * h);
  EXPECT_LT((sim::surface_velocity(g, x) - difference).norm(), 1e-6);
}

std::string with_keys(const std::string& collider_extra) {
  return R"({ "colliders": [ {"shape": "box", "size": [1, 0.1, 1], "position": [0, 1, 0])" + collider_extra +
         R"(} ], "bodies": [ { "mesh": "icosphere:1" } ] })";
}

TEST(ColliderMotion, SceneKeysAreRead) {
  const scene::Scene s = testing_support::scene_from_text(with_keys(
      R"(, "interpolation": "smooth", "keys": [{"time": 0}, {"time": 1, "position": [2, 1, 0], "rotation": [0, 90, 0],
          "scale": 2}])"));
  const sim::ColliderMotion& motion = s.colliders.at(0).motion;
  ASSERT_EQ(motion.keys.size(), 2u);
  EXPECT_EQ(motion.interpolation, KeyInterpolation::Smooth);
  EXPECT_EQ(motion.keys[0].position_m, Vec3(0, 1, 0));  // the collider's own position
  EXPECT_EQ(motion.keys[0].scale, 1.0);
  EXPECT_EQ(motion.keys[1].position_m, Vec3(2, 1, 0));
  EXPECT_EQ(motion.keys[1].scale, 2.0);
  EXPECT_NEAR(motion.keys[1].rotation.angularDistance(Quat(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitY()))), 0.0, 1e-12);
  EXPECT_FALSE(testing_support::scene_from_text(with_keys("")).colliders.at(0).motion.moving());
}

TEST(ColliderMotion, BadKeysAreRefusedWithTheirPath) {
  const auto refuses = [](const std::string& extra, const std::string& words) {
    const std::string message = scene_refusal(with_keys(extra));
    EXPECT_NE(message.find(words), std::string::npos) << extra << " gave: " << message;
  };
  refuses(R"(, "keys": [])", "colliders.0.keys: expected an array of at least one key");
  refuses(R"(, "keys": [{"time": 1}, {"time": 1}])", "colliders.0.keys.1.time: expected a time later than");
  refuses(R"(, "keys": [{"time": 1}, {"time": 0.5}])", "the keys' times must increase");
  refuses(R"(, "keys": [{"position": [0, 0, 0]}])", "colliders.0.keys.0.time: expected the key's time");
  refuses(R"(, "keys": [{"time": 0, "scale": 0}])", "colliders.0.keys.0.scale");
  refuses(R"(, "keys": [{"time": 0, "scale": -1}])", "colliders.0.keys.0.scale");
  refuses(R"(, "keys": [{"time": 0, "speed": 1}])", "colliders.0.keys.0.speed: unknown key");
  refuses(R"(, "interpolation": "smooth")", "colliders.0.interpolation: expected only with \"keys\"");
  refuses(R"(, "keys": [{"time": 0}], "interpolation": "cubic")", "colliders.0.interpolation: expected one of");
}

}  // namespace
