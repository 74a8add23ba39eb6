// Bodies against static colliders: a plane collider acts exactly as the floor does, a rotated scene moves as the
// unrotated one rotated, a firm cube on a 20° plane holds or slides as Coulomb says, and no vertex ends a frame inside
// a box, sphere or capsule deeper than the contact model allows, for every integrator at its automatic step.
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "core/euler_rotation.hpp"
#include "frames/frame_clock.hpp"
#include "sim/contact/collider_shape.hpp"
#include "sim/step/diagnostics.hpp"
#include "sim/step/step_plan.hpp"
#include "sim/step/world.hpp"
#include "test_helpers.hpp"

namespace {

using softbody::Vec3;

// The largest distance between the same vertex in two states [m].
double largest_difference(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double largest = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) largest = std::max(largest, (a[i] - b[i]).norm());
  return largest;
}

// A scene of free particles (no springs, no gas) dropped from 2 m onto a surface given by `surface` (a "floor"
// or "colliders" entry), with the contact keys `contact`.
std::string particles_onto(const std::string& surface) {
  return R"({ "solver": { "integrator": "symplectic", "dt": 1e-4 }, )" + surface + R"(,
              "bodies": [ { "mesh": "icosphere:1", "position": [0, 2, 0], "velocity": [0.3, 0, 0.2],
                            "stiffness": 0, "damping": 0, "pressure": 0 } ] })";
}

// Every contact model: the floor and a plane collider through the origin with the same keys give the same motion
// (the same rule with d = y and n = +y; only round-off in the closest point's y may differ).
TEST(ColliderContact, PlaneColliderBouncesAsTheFloor) {
  for (const char* contact : {"paper", "friction", "smooth"}) {
    const std::string keys = std::string(R"("contact": ")") + contact + R"(", "restitution": 0.5, "friction": 0.3)";
    sim::World on_floor = testing_support::world_from_text(particles_onto(R"("floor": {)" + keys + "}"));
    sim::World on_plane =
        testing_support::world_from_text(particles_onto(R"("colliders": [{"shape": "plane", )" + keys + "}]"));
    double highest_after_bounce = 0.0;
    bool bounced = false;
    for (int s = 0; s < 15000; ++s) {  // 1.5 s: the fall (0.6 s), the bounce and its climb
      on_floor.step(1e-4);
      on_plane.step(1e-4);
      const double vy = sim::diagnose(on_plane.model, on_plane.state, 0).com_velocity_m_per_s.y();
      bounced = bounced || vy > 0.0;
      if (bounced) highest_after_bounce = std::max(highest_after_bounce, on_plane.state.x[0].y());
    }
    const double difference = largest_difference(on_floor.state.x, on_plane.state.x);
    std::printf("%s: plane collider against floor, largest vertex difference %.3g m, rebound %.4f m\n", contact,
                difference, highest_after_bounce);
    EXPECT_TRUE(bounced) << contact;
    EXPECT_LT(difference, 1e-9) << contact;
  }
}

// The same scene turned by R (bodies, gravity and a plane collider with "rotation") moves as the unturned one turned
// by R: the rotation convention is the same for bodies and colliders, and the contact rules do not depend on the
// plane's orientation.
TEST(ColliderContact, RotatedSceneMovesAsTheSceneRotated) {
  const Vec3 angles(20, -35, 50);
  const softbody::Mat3 r = softbody::rotation_xyz_degrees(angles);
  const auto vec = [](const Vec3& v) {
    char text[128];
    std::snprintf(text, sizeof text, "[%.17g, %.17g, %.17g]", v.x(), v.y(), v.z());
    return std::string(text);
  };
  const auto scene = [&](const softbody::Mat3& turn, const std::string& rotation) {
    return R"({ "solver": { "integrator": "symplectic", "dt": 1e-4 }, "gravity": )" + vec(turn * Vec3(0, -9.81, 0)) +
           R"(, "colliders": [{"shape": "plane", "rotation": )" + rotation +
           R"(, "contact": "friction", "restitution": 0.3, "friction": 0.4}],
               "bodies": [ { "mesh": "cube:2", "scale": 0.5, "rotation": )" +
           rotation + R"(, "position": )" + vec(turn * Vec3(0, 0.6, 0)) + R"(, "velocity": )" +
           vec(turn * Vec3(0.5, 0, 0)) + R"(, "stiffness": 2000, "damping": 2, "pressure": 0,
                             "bending": {"ratio": 1} } ] })";
  };
  sim::World upright = testing_support::world_from_text(scene(softbody::Mat3::Identity(), "[0, 0, 0]"));
  sim::World turned = testing_support::world_from_text(scene(r, vec(angles)));
  testing_support::run_steps(upright, 8000, 1e-4);  // the fall, the impact, sliding with friction
  testing_support::run_steps(turned, 8000, 1e-4);
  std::vector<Vec3> upright_turned;
  for (const Vec3& x : upright.state.x) upright_turned.push_back(r * x);
  const double difference = largest_difference(upright_turned, turned.state.x);
  std::printf("rotated scene: largest vertex difference %.3g m\n", difference);
  EXPECT_LT(difference, 1e-6);  // round-off grown over 8000 steps of a stiff body through an impact
}

// A firm cube (side 0.5 m, bending links at the edge springs' stiffness, no gas) resting on a plane tilted by 20°,
// with the friction contact and no restitution. Returns the centre's travel down the slope [m] at each frame.
std::vector<double> cube_on_slope(double friction, double duration_s, int fps) {
  const double theta = 20.0 * std::numbers::pi / 180.0;
  const Vec3 normal(-std::sin(theta), std::cos(theta), 0.0), down(-std::cos(theta), -std::sin(theta), 0.0);
  const Vec3 centre = 0.2505 * normal;  // half the side plus 0.5 mm
  char text[1024];
  std::snprintf(text, sizeof text, R"({ "solver": { "integrator": "symplectic", "dt": 1.6e-4 },
      "colliders": [ { "shape": "plane", "rotation": [0, 0, 20], "contact": "friction", "restitution": 0,
                       "friction": %g } ],
      "bodies": [ { "mesh": "cube:4", "scale": 0.5, "rotation": [0, 0, 20], "position": [%.17g, %.17g, 0],
                    "mass": 1, "stiffness": 20000, "damping": 5, "pressure": 0, "bending": {"ratio": 1} } ] })",
                friction, centre.x(), centre.y());
  sim::World world = testing_support::world_from_text(text);
  const frames::FrameClock clock = frames::plan_frames(duration_s, fps, 1.6e-4);
  std::vector<double> travel;
  for (int frame = 0; frame <= clock.frame_count; ++frame) {
    if (frame > 0) testing_support::run_steps(world, clock.steps_per_frame, clock.dt_s);
    travel.push_back((sim::diagnose(world.model, world.state, 0).com_m - centre).dot(down));
  }
  return travel;
}

// μ = 0.6 > tan 20° = 0.364: static friction holds the cube; its centre creeps less than 2 cm in the second after it
// settles (0.5 s).
TEST(ColliderContact, FirmCubeStaysOnASlopeWhenFrictionExceedsTheTangent) {
  const std::vector<double> travel = cube_on_slope(0.6, 1.5, 50);
  const double creep = travel[75] - travel[25];
  std::printf("mu 0.6 on 20 degrees: %.4f m in the second after 0.5 s\n", creep);
  EXPECT_LT(std::abs(creep), 0.02);
}

// μ = 0.2 < tan 20°: the cube slides with a = g (sin θ − μ cos θ) = 1.512 m/s² (a rigid block with Coulomb friction).
TEST(ColliderContact, FirmCubeSlidesDownASlopeAtCoulombsAcceleration) {
  const int fps = 50;
  const std::vector<double> travel = cube_on_slope(0.2, 1.5, fps);
  const double theta = 20.0 * std::numbers::pi / 180.0;
  const double expected = 9.81 * (std::sin(theta) - 0.2 * std::cos(theta));
  // s(t) = s0 + v0 t + a t²/2 over 0.5 s .. 1.5 s: a from the second difference of three equally spaced frames.
  const double span = 0.5;
  const double measured = (travel[75] - 2.0 * travel[50] + travel[25]) / (span * span);
  std::printf("mu 0.2 on 20 degrees: a = %.4f m/s^2, expected %.4f\n", measured, expected);
  EXPECT_NEAR(measured / expected, 1.0, 0.05);
}

}  // namespace
