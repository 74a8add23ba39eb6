// A copied State is a checkpoint: a fresh world stepped from the copy reaches the same bits as the world
// that never stopped, for every integrator, with floor and body contacts in play.
#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "setup/build_world.hpp"
#include "sim/step/diagnostics.hpp"
#include "sim/step/world.hpp"
#include "test_helpers.hpp"

namespace {

using softbody::Vec3;

struct Case {
  sim::IntegratorKind integrator;
  std::string floor_contact;  // "paper" or "friction"
  bool retry = false;
  double dt_s = 1e-4;
};

// Two small balls: the lower one 4 mm above the floor and falling at 0.5 m/s (it lands after 8 ms), the upper
// one 8 cm above it and falling at 5 m/s (it lands on the lower one after about 17 ms). Both contacts act
// from then on; before, nothing touches (the integrators carry the most then).
sim::World two_ball_world(const Case& c) {
  const std::string solver = R"("solver": { "integrator": ")" + sim::to_string(c.integrator) + R"(", "dt": )" +
                             std::to_string(c.dt_s) + R"(, "retry": )" + (c.retry ? "true" : "false") +
                             R"(, "tolerance": 1e-5 },)";
  return testing_support::world_from_text("{" + solver + R"(
    "floor": { "contact": ")" + c.floor_contact +
                                          R"(", "restitution": 0.4, "friction": 0.6 },
    "collisions": { "restitution": 0.3, "friction": 0.5 },
    "bodies": [
      { "mesh": "icosphere:2", "position": [0, 0.26, 0], "scale": 0.3, "velocity": [0, -0.5, 0], "mass": 0.3,
        "stiffness": 500, "damping": 1, "pressure": 10 },
      { "mesh": "icosphere:2", "position": [0.05, 0.85, 0], "scale": 0.3, "velocity": [0.3, -5, 0], "mass": 0.3,
        "stiffness": 500, "damping": 1, "pressure": 10 } ] })");
}

// The momentum of body b [kg·m/s].
Vec3 momentum_of(const sim::World& world, std::size_t b) {
  return sim::diagnose(world.model, world.state, b).momentum_kg_m_per_s;
}

// Which contacts acted while a world ran (summed over the pieces of the run): momentum that gravity alone
// does not explain. Body contacts conserve the two balls' total momentum, so what the pair gained beyond gravity came
// from the floor; what the upper ball gained beyond gravity came from the lower one.
struct ContactsSeen {
  double floor_impulse = 0.0;  // |Δ(p0 + p1) − (m0 + m1) g Δt| [kg·m/s]
  double body_impulse = 0.0;   // |Δp1 − m1 g Δt|
  bool both() const { return floor_impulse > 0.01 && body_impulse > 0.01; }
};

// Advances to `time_s` frame by frame, as the frame loops do (adaptive steps land on every frame time, so
// a run and its resumed copy must stop at the same ones): fixed steps of dt, or the adaptive integrator's own.
constexpr double kFrame_s = 5e-4;
ContactsSeen run_to(sim::World& world, double time_s, double dt, ContactsSeen seen = {}) {
  const Vec3 p0 = momentum_of(world, 0), p1 = momentum_of(world, 1);
  const double t0 = world.state.time_s;
  for (long frame = std::lround(t0 / kFrame_s) + 1; frame <= std::lround(time_s / kFrame_s); ++frame) {
    if (world.adaptive()) {
      world.advance_to(static_cast<double>(frame) * kFrame_s);
    } else {
      while (world.state.time_s < static_cast<double>(frame) * kFrame_s - 0.5 * dt) world.step(dt);
    }
  }
  const Vec3 gravity_impulse_per_kg = world.model.gravity_m_per_s2 * (world.state.time_s - t0);
  const double m1 = world.model.bodies[1].masses.total_kg;
  const double m = world.model.bodies[0].masses.total_kg + m1;
  seen.floor_impulse += (momentum_of(world, 0) + momentum_of(world, 1) - p0 - p1 - m * gravity_impulse_per_kg).norm();
  seen.body_impulse += (momentum_of(world, 1) - p1 - m1 * gravity_impulse_per_kg).norm();
  return seen;
}

class Checkpoint : public ::testing::TestWithParam<Case> {};

// Vertices whose x or v differ in any bit (== on doubles, not a tolerance).
std::size_t differing_vertices(const sim::State& a, const sim::State& b) {
  std::size_t differing = 0;
  for (std::size_t i = 0; i < a.x.size(); ++i) differing += a.x[i] != b.x[i] || a.v[i] != b.v[i];
  return differing;
}

// Copies taken at several moments (before any contact, where a step carries the most over, and in the middle
// of both contacts), each resumed in a fresh world (a new model and workspace, as after a restart) to the end.
TEST_P(Checkpoint, SteppingFromACopiedStateGivesTheSameBits) {
  const Case c = GetParam();
  constexpr double kEnd_s = 0.05;
  sim::World uninterrupted = two_ball_world(c);
  std::vector<sim::State> copies;
  ContactsSeen before;
  for (double t : {0.001, 0.005, 0.02}) {
    before = run_to(uninterrupted, t, c.dt_s, before);
    if (t == 0.02) {
      EXPECT_TRUE(before.both()) << "before the copy: floor impulse " << before.floor_impulse << " kg m/s, body "
                                 << before.body_impulse << " kg m/s";
    }
    copies.push_back(uninterrupted.state);
  }
  const ContactsSeen after = run_to(uninterrupted, kEnd_s, c.dt_s);
  EXPECT_TRUE(after.both()) << "after the last copy: floor impulse " << after.floor_impulse << " kg m/s, body "
                            << after.body_impulse << " kg m/s";
  if (c.retry) {
    EXPECT_GT(uninterrupted.state.retried_steps, 0) << "the retry path was exercised";
  }

  for (const sim::State& copy : copies) {
    sim::World resumed = two_ball_world(c);
    resumed.state = copy;
    run_to(resumed, kEnd_s, c.dt_s);
    EXPECT_EQ(resumed.state.steps, uninterrupted.state.steps);
    EXPECT_EQ(resumed.state.time_s, uninterrupted.state.time_s);
    EXPECT_EQ(resumed.state.rejected_steps, uninterrupted.state.rejected_steps);
    EXPECT_EQ(resumed.state.retry_substeps, uninterrupted.state.retry_substeps);
    ASSERT_EQ(resumed.state.x.size(), uninterrupted.state.x.size());
    EXPECT_EQ(differing_vertices(resumed.state, uninterrupted.state), 0u)
        << "vertices whose x or v differ after resuming from the copy taken at t = " << copy.time_s << " s";
  }
}

std::vector<Case> cases() {
  std::vector<Case> all;
  for (const sim::IntegratorInfo& integrator : sim::kIntegrators) {
    for (const char* contact : {"paper", "friction"}) all.push_back({integrator.kind, contact});
  }
  // Retried steps: 2 to 3 times their stable dt, so that steps are redone in substeps.
  all.push_back({sim::IntegratorKind::Symplectic, "paper", true, 1e-3});
  all.push_back({sim::IntegratorKind::Verlet, "paper", true, 8e-4});
  return all;
}

INSTANTIATE_TEST_SUITE_P(EveryIntegrator, Checkpoint, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& test) {
                           return sim::to_string(test.param.integrator) + "_" + test.param.floor_contact +
                                  (test.param.retry ? "_retry" : "");
                         });

}  // namespace
