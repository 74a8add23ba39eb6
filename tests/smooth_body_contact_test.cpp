// The smooth contact between bodies (collisions.contact "smooth"): a force inside a(x, v) that conserves
// momentum exactly, bounces bodies apart, holds a ball on a box without sinking, and converges as dt shrinks.
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "sim/contact/body_collision.hpp"
#include "sim/step/diagnostics.hpp"
#include "sim/step/world.hpp"
#include "test_helpers.hpp"

namespace {

using softbody::Vec3;
using testing_support::total_momentum;

// Two balls meet head-on (no gravity, no floor): each contact force acts on the vertex (+F) and on the
// triangle's corners (−w_k F, Σ w_k = 1), so the momentum of the pair is kept to round-off through the whole
// collision, with rk4's stages seeing the contact as any other force.
TEST(SmoothBodyContact, HeadOnCollisionConservesMomentumAndSeparates) {
  sim::World world = testing_support::world_from_text(R"({
    "gravity": [0, 0, 0],
    "solver": { "integrator": "rk4" },
    "collisions": { "contact": "smooth", "restitution": 0.8, "friction": 0.3 },
    "bodies": [
      { "mesh": "icosphere:2", "position": [-1.3, 0, 0], "velocity": [2, 0, 0], "mass": 1.0,
        "stiffness": 2000.0, "damping": 0.5, "pressure": 100.0 },
      { "mesh": "icosphere:2", "position": [1.3, 0.1, 0], "velocity": [-2, 0, 0], "mass": 1.5,
        "stiffness": 2000.0, "damping": 0.5, "pressure": 100.0 } ] })");
  const Vec3 before = total_momentum(world);
  testing_support::run_steps(world, 10000, 1e-4);  // 1 s: they touch after ~0.08 s
  const Vec3 after = total_momentum(world);
  EXPECT_LT((after - before).norm(), 1e-12) << before.transpose() << " -> " << after.transpose();
  const double vx_left = sim::diagnose(world.model, world.state, 0).com_velocity_m_per_s.x();
  const double vx_right = sim::diagnose(world.model, world.state, 1).com_velocity_m_per_s.x();
  std::printf("after the collision: vx %.4f and %.4f m/s\n", vx_left, vx_right);
  EXPECT_LT(vx_left, -0.5) << "the lighter ball bounces back";
  EXPECT_GT(vx_right, 0.2) << "the heavier one too";
}

// A ball dropped onto a soft box on the smooth floor: the stack (the scene of the two tests below).
const char* kStack = R"({
    "solver": { "integrator": "rk4" },
    "floor": { "contact": "smooth", "restitution": 0.2, "friction": 0.8 },
    "collisions": { "contact": "smooth", "restitution": 0.2, "friction": 0.8 },
    "bodies": [
      { "mesh": "cube:4", "position": [0, 0.5, 0], "mass": 1.0, "stiffness": 3000.0, "damping": 3.0, "pressure": 40.0 },
      { "mesh": "icosphere:2", "position": [0.05, 1.6, 0], "scale": 0.5, "mass": 0.5, "stiffness": 2000.0,
        "damping": 2.0, "pressure": 40.0 } ] })";

// The ball lands on the box and stays on it without sinking in: at every sample over 0.8 s, no vertex of
// the ball is inside the box (generalised winding number < ½) and the ball is on top. (It does not come to
// rest: it keeps bouncing a little on the contact springs, and the inflated box's top is a dome, so after
// about a second it rolls off it, as a ball on a pillow would.)
TEST(SmoothBodyContact, BallOnABoxDoesNotSinkIn) {
  sim::World world = testing_support::world_from_text(kStack);
  const sim::Body& box = world.model.bodies[0];
  double deepest = 0.0, lowest = 1e300;
  int inside = 0;
  for (int sample = 0; sample < 16; ++sample) {
    testing_support::run_steps(world, 500, 1e-4);  // 50 ms
    for (const Vec3& p : world.model.of(world.model.bodies[1], world.state.x)) {
      const double w = sim::winding_number(world.model.of(box, world.state.x), box.topology.faces, p);
      deepest = std::max(deepest, w);
      if (w > 0.5) ++inside;
    }
    lowest = std::min(lowest, sim::diagnose(world.model, world.state, 1).min_y_m);
  }
  std::printf("stack: ball's lowest vertex %.4f m, largest winding number %.3g\n", lowest, deepest);
  EXPECT_EQ(inside, 0) << "largest winding number " << deepest;
  EXPECT_GT(lowest, 0.95) << "the ball stays on top of the box (1 m tall)";
}

// The stack as dt shrinks: the smooth contact is part of the ODE, so the ball's position after its landing
// converges. Measured (rk4, 0.8 s): successive differences 1.1e-4 and 2.8e-6 m for dt 4e-4 → 2e-4 → 1e-4 s.
TEST(SmoothBodyContact, TheStackConvergesAsTheStepShrinks) {
  std::vector<Vec3> com;
  for (double dt : {4e-4, 2e-4, 1e-4}) {
    sim::World world = testing_support::world_from_text(kStack);
    testing_support::run_steps(world, std::llround(0.8 / dt), dt);
    com.push_back(sim::diagnose(world.model, world.state, 1).com_m);
  }
  const double coarse = (com[0] - com[1]).norm(), fine = (com[1] - com[2]).norm();
  std::printf("stack convergence: |dx| %.3g then %.3g m, ratio %.2f (order %.2f)\n", coarse, fine, coarse / fine,
              std::log2(coarse / fine));
  EXPECT_GT(coarse / fine, 8.0) << "at least third order";
  EXPECT_LT(fine, 1e-5);
}

}  // namespace
