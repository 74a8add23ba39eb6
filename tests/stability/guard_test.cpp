// The divergence guard: what it reports, the exit status, the frames before, retries, and no tunnelling.
#include <cmath>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "core/errors.hpp"
#include "sim/step/diagnostics.hpp"
#include "sim/step/guard.hpp"
#include "sim/step/stability.hpp"
#include "test_helpers.hpp"

namespace {

using testing_support::run_softbody;
using testing_support::world_from_text;

// scenes/bounce.json's ball, coarser, in free flight.
std::string ball(const std::string& solver, const std::string& extra = "") {
  return R"({ "gravity": [0, -9.81, 0], "solver": )" + solver + extra +
         R"(, "bodies": [ { "mesh": "icosphere:2", "position": [0, 3, 0], "stiffness": 3000, "damping": 0.5, "pressure": 30 } ] })";
}

std::string diverge_message(sim::World& world, double dt, int steps) {
  try {
    for (int s = 0; s < steps; ++s) world.step(dt);
  } catch (const softbody::DivergedError& e) {
    return e.what();
  }
  return "";
}

// Forward Euler above c/k = 1.67e-4 s: stopped with time, step, body, vertex, what, and the stable dt.
TEST(Guard, MessageSaysWhenWhereWhatAndWhichDtIsStable) {
  sim::World world = world_from_text(ball(R"({ "integrator": "euler" })"));
  const std::string message = diverge_message(world, 2.0e-4, 20000);
  std::printf("%s\n", message.c_str());
  ASSERT_FALSE(message.empty()) << "forward Euler at 1.2x its damper limit must be stopped";
  EXPECT_EQ(message.rfind("diverged at t = ", 0), 0u);
  EXPECT_NE(message.find("dt = 0.0002 s, euler): body 0, vertex "), std::string::npos);
  EXPECT_NE(message.find("runaway speed"), std::string::npos);
  EXPECT_NE(message.find("estimated stable: dt <= 0.00015 s for euler"), std::string::npos);
  EXPECT_NE(message.find("vbd takes every force implicitly, at any dt"), std::string::npos);
}

// Turning the ball inside out (a mirror image) is caught as an inverted volume on the next step.
TEST(Guard, InvertedVolumeIsCaught) {
  sim::World world = world_from_text(ball(R"({ "integrator": "symplectic" })"));
  for (softbody::Vec3& x : world.state.x) x.x() = -x.x();
  // The volume is checked every kFullCheckInterval steps (and before every frame).
  const std::string message = diverge_message(world, 1e-4, sim::kFullCheckInterval);
  EXPECT_NE(message.find("volume inverted"), std::string::npos) << message;
}

// The same ball at the same dt with solver.retry: the failed step is redone as substeps, and the run
// goes on with them to the end.
TEST(Guard, RetrySplitsFailedStepsInsteadOfStopping) {
  sim::World world = world_from_text(ball(R"({ "integrator": "euler", "retry": true })"));
  EXPECT_NO_THROW(testing_support::run_steps(world, 5000, 2.0e-4));
  EXPECT_GT(world.state.retried_steps, 0);
  EXPECT_EQ(world.state.retry_substeps, 2) << "half of 2e-4 s is below the 1.67e-4 s limit";
  EXPECT_TRUE(world.state.x[0].allFinite());
}

// The CLI: exit status 3, the message on stderr, and the CSV keeps the frames before, all finite.
TEST(Guard, CliExitsWithThreeAndKeepsTheValidFrames) {
  const std::string csv = (testing_support::scratch_dir("guard_cli") / "simulation.csv").string();
  const auto result = run_softbody("simulate scenes/bounce.json --csv " + csv + " --set solver.dt=2e-4");
  EXPECT_EQ(result.exit_status, 3) << result.output;
  EXPECT_NE(result.output.find("diverged at t = "), std::string::npos) << result.output;
  std::ifstream in(csv);
  std::string line;
  int rows = 0;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    ++rows;
    EXPECT_EQ(line.find("nan"), std::string::npos) << line;
    EXPECT_EQ(line.find("inf"), std::string::npos) << line;
  }
  EXPECT_GE(rows, 2) << "the frames before the divergence are kept";
}

// A stiff ball hitting the floor at 50 m/s bounces off it. No step carries a vertex more than the travel
// limit's tenth of the shortest edge into the floor (measured before the floor puts it back), the ball is not
// crushed (its centre of mass stays above half its radius), and it comes back up.
TEST(Guard, FiftyMetresPerSecondImpactDoesNotTunnel) {
  sim::World world = world_from_text(R"({ "gravity": [0, -9.81, 0], "floor": { "height": 0, "contact": "paper" },
    "solver": { "integrator": "symplectic" },
    "bodies": [ { "mesh": "icosphere:2", "position": [0, 1.5, 0], "velocity": [0, -50, 0],
                  "stiffness": 3e5, "damping": 5, "pressure": 300 } ] })");
  const double dt =
      sim::kAutoDtSafety * sim::estimate_stability(world.model, world.state).stable_dt(sim::IntegratorKind::Symplectic);
  const double edge = sim::body_stats(world.model.bodies[0], world.state.x).edge_min_m;
  double lowest_com = 10.0, deepest = 0.0;
  const int steps = static_cast<int>(0.2 / dt);
  for (int s = 0; s < steps; ++s) {
    world.step(dt);
    lowest_com = std::min(lowest_com, sim::diagnose(world.model, world.state, 0).com_m.y());
    deepest = std::max(deepest, world.workspace.deepest_floor_penetration_m);
  }
  const sim::BodyDiagnostics end = sim::diagnose(world.model, world.state, 0);
  std::printf(
      "dt = %.3g s: deepest vertex %.3g m into the floor in one step (%.3f shortest edges), lowest centre of "
      "mass %.3f m, after 0.2 s %.3f m moving at %.2f m/s\n",
      dt, deepest, deepest / edge, lowest_com, end.com_m.y(), end.com_velocity_m_per_s.y());
  EXPECT_LE(deepest, sim::kTravelFraction * edge);
  EXPECT_GT(lowest_com, 0.5) << "crushed: the ball's radius is 1 m";
  EXPECT_GT(end.com_velocity_m_per_s.y(), 0.0) << "it bounced back up";
}

}  // namespace
