// A gas-filled body's impact duration (sim/step/impact_duration.hpp), which `softbody info` prices vbd's impact steps
// by: against the time a simulated ball stays on the smooth floor.
#include <algorithm>
#include <cstdio>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "sim/step/impact_duration.hpp"
#include "support.hpp"

namespace {

// scenes/bounce_smooth.json's floor and ball (1 kg, k 1000 N/m, c 1 N·s/m) at icosphere:3 and nRT `pressure` [J],
// thrown down from just above the floor.
std::string ball_on_the_floor(double pressure) {
  return R"({
    "gravity": [0, -9.81, 0],
    "floor": { "height": 0.0, "contact": "smooth", "time_constant": 0.002, "restitution": 0.5, "friction": 0.5,
               "slip_speed": 0.1, "smoothing": 0.01 },
    "bodies": [ { "mesh": "icosphere:3", "position": [0, 1.2, 0], "velocity": [1, -5, 0],
                  "mass": 1.0, "stiffness": 1000.0, "damping": 1.0, "pressure": )" +
         std::to_string(pressure) + " } ] }";
}

// How long some vertex is within the floor's 1 cm skin in the first impact, the world stepped by `dt` [s].
double time_on_the_floor(sim::World& world, double dt) {
  double first = -1.0, last = -1.0;
  for (int n = 0; n < 600; ++n) {
    world.step(dt);
    double lowest = std::numeric_limits<double>::infinity();
    for (const auto& x : world.state.x) lowest = std::min(lowest, x.y());
    const bool touching = lowest < 0.01;
    if (touching && first < 0.0) first = world.state.time_s;
    if (touching) last = world.state.time_s;
    if (!touching && first >= 0.0) break;
  }
  return last - first;
}

// The estimate π √(m / (2π R P)) is within 10 % of the simulated contact for the bounce's ball at nRT 100 and 200 J
// (vbd at 1 ms steps, which shrinks them itself through the impact).
TEST(ImpactDuration, GasBallsStayOnTheFloorAboutAsLongAsEstimated) {
  for (const double pressure : {100.0, 200.0}) {
    sim::World world = integrator_tests::make_world(ball_on_the_floor(pressure), sim::IntegratorKind::Vbd);
    const double estimate = sim::gas_impact_duration(world.model.bodies[0]);
    const double simulated = time_on_the_floor(world, 1e-3);
    std::printf("nRT %.0f J: on the floor %.3f s, estimated %.3f s\n", pressure, simulated, estimate);
    EXPECT_NEAR(estimate, simulated, 0.1 * simulated) << "nRT " << pressure;
  }
}

TEST(ImpactDuration, IsZeroWithoutGas) {
  sim::World world = integrator_tests::make_world(ball_on_the_floor(0.0), sim::IntegratorKind::Vbd);
  EXPECT_EQ(sim::gas_impact_duration(world.model.bodies[0]), 0.0);
}

}  // namespace
