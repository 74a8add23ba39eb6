// No vertex inside a collider deeper than its contact model allows, at any frame, for every integrator at the step
// "auto" chooses: a soft ball dropped onto a box's edge, a sphere, a tilted capsule (so that it also slides off), the
// box as a cube mesh, a tilted square sheet (an open mesh) and a ring (a torus mesh).
// The impulse models put every vertex back on the surface after each step: none inside. The smooth contact lets a
// vertex sink until its spring has stopped it: about v τ for an impact at v (a spring m/τ² taking ½ m v²), plus the
// smoothing depth δ over which the spring ramps up.
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "sim/contact/collider_shape.hpp"
#include "sim/step/world.hpp"
#include "test_helpers.hpp"

namespace {

using softbody::Vec3;

constexpr double kDrop_m = 0.6;            // from the ball's lowest point to the collider's top
constexpr double kTimeConstant_s = 0.002;  // the smooth contact's τ (the default)
constexpr double kSmoothing_m = 0.002;     // its δ (the default)

const char* const kShapes[] = {
    R"({"shape": "box", "position": [0.25, 0, 0], "size": [0.5, 0.5, 0.5], "rotation": [0, 0, 10]})",
    R"({"shape": "sphere", "position": [0.1, 0, 0], "radius": 0.25})",
    R"({"shape": "capsule", "position": [0, 0, 0], "radius": 0.25, "length": 0.6, "rotation": [80, 0, 0]})",
    // The box as a closed mesh, and an open square sheet (1 cm thick) tilted as the box is.
    R"({"shape": "mesh", "mesh": "cube:1", "scale": 0.5, "position": [0.25, 0, 0], "rotation": [0, 0, 10]})",
    R"({"shape": "mesh", "mesh": "data/quad.obj", "scale": 0.4, "position": [0.25, 0.25, 0], "rotation": [0, 0, 10]})",
    // The ring of scenes/ring.json (a torus, not convex), the ball landing on its tube's top off the middle.
    R"({"shape": "mesh", "mesh": "torus:48,16", "scale": 0.6, "position": [0.5, 0, 0]})",
};

std::string ball_onto(const std::string& shape, const std::string& contact, const sim::IntegratorInfo& integrator) {
  const std::string step = integrator.frame_substeps ? R"("substeps": "auto")" : R"("dt": "auto")";
  std::string collider = shape;
  collider.insert(collider.size() - 1, R"(, "contact": ")" + contact + R"(", "restitution": 0.3, "friction": 0.4)");
  return R"({ "duration": 0.8, "fps": 30, "solver": { "integrator": ")" + std::string(integrator.name) + R"(", )" +
         step + R"( }, "colliders": [)" + collider + R"(],
      "bodies": [ { "mesh": "icosphere:2", "scale": 0.2, "position": [0, )" +
         std::to_string(0.25 + kDrop_m + 0.2) +
         R"(, 0], "mass": 1, "stiffness": 600, "damping": {"ratio": 0.3}, "pressure": {"inflation": 0.05} } ] })";
}

// The deepest any vertex is inside the collider at any frame [m].
double deepest_at_frames(const std::string& text) {
  double deepest = 0.0;
  testing_support::run_scene_frames(text, [&](double, const sim::World& world) {
    const sim::ColliderGeometry& collider = world.model.colliders.at(0).geometry;
    for (const Vec3& x : world.state.x) deepest = std::max(deepest, -sim::nearest_surface(collider, x).distance_m);
  });
  return deepest;
}

TEST(ColliderDepth, ImpulseContactsLeaveNoVertexInside) {
  for (const char* contact : {"paper", "friction"}) {
    for (const sim::IntegratorInfo& integrator : sim::kIntegrators) {
      for (const char* shape : kShapes) {
        const double deepest = deepest_at_frames(ball_onto(shape, contact, integrator));
        EXPECT_LT(deepest, 1e-12) << contact << ", " << integrator.name << ", " << shape;
      }
    }
  }
}

TEST(ColliderDepth, SmoothContactStaysWithinItsSkin) {
  const double impact_speed = std::sqrt(2.0 * 9.81 * kDrop_m);        // m/s
  const double skin = impact_speed * kTimeConstant_s + kSmoothing_m;  // v τ + δ = 8.9 mm
  for (const sim::IntegratorInfo& integrator : sim::kIntegrators) {
    for (const char* shape : kShapes) {
      const double deepest = deepest_at_frames(ball_onto(shape, "smooth", integrator));
      std::printf("smooth, %-10s %.2f mm (skin %.2f mm): %s\n", std::string(integrator.name).c_str(), 1e3 * deepest,
                  1e3 * skin, shape);
      EXPECT_LT(deepest, skin) << integrator.name << ", " << shape;
    }
  }
}

}  // namespace
