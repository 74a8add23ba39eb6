// Floor contact with restitution and Coulomb friction: a sliding ball starts to roll, a resting one stays.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "sim/step/diagnostics.hpp"
#include "sim/step/world.hpp"
#include "test_helpers.hpp"

namespace {

using softbody::Vec3;

// A firm pressurised ball (a thin shell: all mass on the surface) touching the floor at its lowest
// vertex, sliding at `speed` without spin.
std::string ball_on_floor(double speed) {
  return R"({ "floor": { "contact": "friction", "restitution": 0.0, "friction": 0.5 },
              "bodies": [ { "mesh": "icosphere:3", "position": [0, 1.0, 0], "velocity": [)" +
         std::to_string(speed) + R"(, 0, 0],
                            "mass": 1.0, "stiffness": 10000.0, "damping": 5.0, "pressure": 200.0 } ] })";
}

// Angular velocity about z from the angular momentum about the centre of mass: ω_z = L_z / I_zz.
double spin_z(const sim::World& world) {
  const sim::Body& body = world.model.bodies[0];
  const sim::BodyDiagnostics d = sim::diagnose(world.model, world.state, 0);
  double angular_momentum = 0.0, inertia = 0.0;
  for (int i = 0; i < body.vertex_count; ++i) {
    const Vec3 r = world.state.x[i] - d.com_m;
    const Vec3 u = world.state.v[i] - d.com_velocity_m_per_s;
    angular_momentum += body.masses.kg[i] * r.cross(u).z();
    inertia += body.masses.kg[i] * (r.x() * r.x() + r.y() * r.y());
  }
  return angular_momentum / inertia;
}

// Sliding friction slows the centre and spins the ball up until the contact point is at rest:
// v = ω R. Momentum and angular momentum about the contact point give v = v0 / (1 + I/(M R²)),
// and for a thin spherical shell I = (2/3) M R², so v = 0.6 v0.
TEST(FrictionContact, SlidingShellSettlesIntoRollingAtSixTenthsOfItsSpeed) {
  const double v0 = 2.0, dt = 2e-5;
  sim::World world = testing_support::world_from_text(ball_on_floor(v0));
  testing_support::run_steps(world, std::llround(0.6 / dt), dt);  // sliding phase: over within ~0.15 s
  double mean_vx = 0.0, mean_spin = 0.0;
  const int samples = 20;
  for (int s = 0; s < samples; ++s) {
    testing_support::run_steps(world, std::llround(0.02 / dt), dt);
    mean_vx += sim::diagnose(world.model, world.state, 0).com_velocity_m_per_s.x() / samples;
    mean_spin += spin_z(world) / samples;
  }
  std::printf("rolling: v/v0 = %.4f, -omega R / v = %.4f\n", mean_vx / v0, -mean_spin / mean_vx);
  // Measured 0.575 on icosphere:3: the faceted ball loses a little to each facet it rolls over.
  EXPECT_NEAR(mean_vx / v0, 0.6, 0.04);
  const double radius = 1.0;
  EXPECT_NEAR(-mean_spin * radius / mean_vx, 1.0, 0.1) << "rolling without slipping: ω R = v";
}

TEST(FrictionContact, BallAtRestDoesNotStartToRoll) {
  const double dt = 2e-5;
  sim::World world = testing_support::world_from_text(ball_on_floor(0.0));
  testing_support::run_steps(world, std::llround(1.0 / dt), dt);
  const sim::BodyDiagnostics d = sim::diagnose(world.model, world.state, 0);
  EXPECT_LT(std::hypot(d.com_m.x(), d.com_m.z()), 1e-6) << d.com_m.transpose();
  EXPECT_LT(std::hypot(d.com_velocity_m_per_s.x(), d.com_velocity_m_per_s.z()), 1e-6);
  EXPECT_LT(std::abs(spin_z(world)), 1e-5);
  EXPECT_GE(d.min_y_m, 0.0);
}

// No springs, no gas: every vertex is a free particle, so each rebounds with e × its impact speed and
// climbs back to e² of its drop height.
TEST(FrictionContact, RestitutionSetsTheReboundHeight) {
  sim::World world = testing_support::world_from_text(R"({
      "floor": { "contact": "friction", "restitution": 0.5, "friction": 0.0 },
      "bodies": [ { "mesh": "icosphere:1", "position": [0, 2, 0], "stiffness": 0, "damping": 0, "pressure": 0 } ] })");
  const std::vector<Vec3>& x = world.state.x;
  const std::size_t lowest =
      std::min_element(x.begin(), x.end(), [](const Vec3& a, const Vec3& b) { return a.y() < b.y(); }) - x.begin();
  const double drop_height = x[lowest].y();
  bool bounced = false;
  double peak = 0.0;
  for (int step = 0; step < 15000; ++step) {
    world.step(1e-4);
    const double y = world.state.x[lowest].y();
    EXPECT_GE(y, 0.0);
    if (y == 0.0) bounced = true;
    if (bounced) peak = std::max(peak, y);
  }
  ASSERT_TRUE(bounced);
  // Forward Euler's discrete fall adds O(h) to the speeds: 1 % is ample at h = 1e-4 s.
  EXPECT_NEAR(peak / drop_height, 0.25, 0.01);
}

}  // namespace
