// Bodies against keyframed colliders, for every integrator at its automatic step: a body on a platform that moves
// sideways at constant speed ends moving with it (the friction contact and the smooth one act on the velocity
// relative to the surface), and a paddle that hits a resting ball gives it momentum along the paddle's motion, of
// the order of what an immovable wall moving at the paddle's speed gives ((1 + e) M U for a rigid ball).
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "sim/step/diagnostics.hpp"
#include "sim/step/world.hpp"
#include "test_helpers.hpp"

namespace {

using softbody::Vec3;

std::string step_keys(const sim::IntegratorInfo& integrator) {
  return std::string(R"("integrator": ")") + std::string(integrator.name) + R"(", )" +
         (integrator.frame_substeps ? R"("substeps": "auto")" : R"("dt": "auto")");
}

constexpr double kPlatformSpeed_m_per_s = 0.5;

// A firm cube dropped 1 cm onto a 2 m platform sliding along +x at 0.5 m/s for 3 s.
std::string cube_on_platform(const std::string& contact, const sim::IntegratorInfo& integrator) {
  return R"({ "duration": 1.5, "fps": 30, "solver": { )" + step_keys(integrator) + R"( },
      "colliders": [ { "shape": "box", "size": [2, 0.1, 2], "contact": ")" +
         contact + R"(", "restitution": 0, "friction": 0.8,
                       "keys": [ {"time": 0, "position": [0, 0, 0]}, {"time": 3, "position": [1.5, 0, 0]} ] } ],
      "bodies": [ { "mesh": "cube:2", "scale": 0.2, "position": [0, 0.16, 0], "mass": 1, "stiffness": 2000,
                    "damping": 2, "pressure": 0 } ] })";
}

// xpbd with the smooth contact takes 40 substeps a frame, not its automatic 13: its prediction applies the
// regularised friction explicitly, a damping of rate μ N / (m ε) (235/s on this cube's most loaded vertices), and at
// 13 substeps the slip it has to take out each substep overshoots: the cube jitters at 0.1 m/s around the platform's
// speed (docs/guide/colliders.md says so).
TEST(MovingCollider, PlatformCarriesABodyWithIt) {
  for (const char* contact : {"friction", "smooth"}) {
    for (const sim::IntegratorInfo& integrator : sim::kIntegrators) {
      std::string text = cube_on_platform(contact, integrator);
      if (integrator.kind == sim::IntegratorKind::Xpbd && std::string(contact) == "smooth") {
        text.replace(text.find(R"("substeps": "auto")"), 18, R"("substeps": 40)");
      }
      // The mean velocity over the last half second (the soft cube rocks a little on its corners meanwhile).
      Vec3 com_at_1s = Vec3::Zero();
      const sim::World world = testing_support::run_scene_frames(text, [&](double t, const sim::World& w) {
        if (std::abs(t - 1.0) < 1e-9) com_at_1s = sim::diagnose(w.model, w.state, 0).com_m;
      });
      const Vec3 v = (sim::diagnose(world.model, world.state, 0).com_m - com_at_1s) / 0.5;
      std::printf("%-8s %-10s body's mean velocity from 1 to 1.5 s: (%.4f, %.4f, %.4f) m/s, platform's %.2f\n", contact,
                  std::string(integrator.name).c_str(), v.x(), v.y(), v.z(), kPlatformSpeed_m_per_s);
      // Moving with the platform: within 2 % of its speed, and neither sinking nor lifting off.
      EXPECT_NEAR(v.x(), kPlatformSpeed_m_per_s, 0.02 * kPlatformSpeed_m_per_s) << contact << ", " << integrator.name;
      EXPECT_LT(std::abs(v.y()) + std::abs(v.z()), 0.01) << contact << ", " << integrator.name;
    }
  }
}

// Without friction the platform slides away under the body, which keeps (almost) still: the carrying is friction's.
TEST(MovingCollider, WithoutFrictionThePlatformSlidesAwayUnderTheBody) {
  std::string text = cube_on_platform("friction", sim::kIntegrators[1]);
  text.replace(text.find(R"("friction": 0.8)"), 15, R"("friction": 0.0)");
  const sim::World world = testing_support::run_scene_frames(text);
  EXPECT_LT(std::abs(sim::diagnose(world.model, world.state, 0).com_velocity_m_per_s.x()), 0.01);
}

constexpr double kPaddleSpeed_m_per_s = 3.0;
constexpr double kBallMass_kg = 0.5;

// No gravity: a ball at rest at the origin, a paddle (a 4 cm board) swung along +x at 3 m/s through where it is.
std::string paddle_hits_ball(const std::string& contact, const sim::IntegratorInfo& integrator) {
  return R"({ "duration": 0.4, "fps": 30, "gravity": [0, 0, 0], "solver": { )" + step_keys(integrator) + R"( },
      "colliders": [ { "shape": "box", "size": [0.04, 0.4, 0.4], "contact": ")" +
         contact + R"(", "restitution": 0.5, "friction": 0.3,
                       "keys": [ {"time": 0, "position": [-0.3, 0, 0]}, {"time": 0.13333333333333333,
                                  "position": [0.1, 0, 0]} ] } ],
      "bodies": [ { "mesh": "icosphere:2", "scale": 0.1, "mass": 0.5, "stiffness": 600, "damping": {"ratio": 0.3},
                    "pressure": {"inflation": 0.05} } ] })";
}

TEST(MovingCollider, PaddleGivesTheBallMomentumAlongItsMotion) {
  for (const char* contact : {"paper", "friction", "smooth"}) {
    for (const sim::IntegratorInfo& integrator : sim::kIntegrators) {
      const sim::World world = testing_support::run_scene_frames(paddle_hits_ball(contact, integrator));
      const Vec3 p = testing_support::total_momentum(world);
      const double per_wall = p.x() / (kBallMass_kg * kPaddleSpeed_m_per_s);  // 1: moves at U, 2: rigid elastic
      std::printf("%-8s %-10s ball's momentum (%.4f, %.4f, %.4f) kg m/s = %.3f M U along x\n", contact,
                  std::string(integrator.name).c_str(), p.x(), p.y(), p.z(), per_wall);
      // Along the paddle's motion, at least U (it leaves the paddle, which then stops) and at most (1 + e) U
      // and a little (a soft ball's rebound adds its stored spring energy).
      EXPECT_GT(p.x(), 0.99 * p.norm()) << contact << ", " << integrator.name;
      EXPECT_GT(per_wall, 0.95) << contact << ", " << integrator.name;
      EXPECT_LT(per_wall, 2.1) << contact << ", " << integrator.name;
    }
  }
}

}  // namespace
